import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { recordedPage, viewsReady } from './pages';
import { useHarness } from './useHarness';
import { addRules, measuredFreeArea, outside, viewBoxes, type ViewBoxes } from './layoutBoxes';
import { compareStrips } from '../../src/sim/compare/compareLayout';
import { figurePictures } from '../../src/sim/teaching/teachingFigures';
import { contains, overlaps, type Rect } from '../../src/sim/layout/rect';

/**
 * Nothing the page draws is hidden under a panel: the compare strips, the teaching views and every overlay (Fresnel plot,
 * physics panel, compare labels, captions, the labels on the sea) lie in the part of the
 * canvas that the control panel and the lessons drawer leave free, on a laptop, a 1280-px
 * screen and a phone; inside an <oceano-view>, every overlay and the lesson card lie inside
 * the figure's box, down to 320 × 180. Boxes are measured in headless Chromium; the free
 * part is measured by the test from the panels' boxes, not read from the page.
 */
const harness = useHarness();

/** The stylesheet rules as they were before the free area: the negative control. */
const OLD_LAYOUT = `
  .oceano-compare { left: 0 !important; top: 0 !important; width: 100% !important; height: 100% !important; }
  .oceano-fresnel-plot { left: 12px !important; bottom: 54px !important; right: auto !important; top: auto !important; max-width: calc(100% - 24px) !important; max-height: calc(100% - 66px) !important; }
  .oceano-physics { left: 8px !important; bottom: 8px !important; width: 370px !important; max-height: calc(100% - 16px) !important; }
  .oceano-play { left: 10px !important; bottom: 10px !important; }
  .oceano-lesson-label-hullPoints.oceano-lesson-label-leftwards { translate: 0 -50% !important; padding: 0 5px 0 14px !important; }
`;

/** Opens a lesson through the API (with extra parameters), then draws and places everything once its parts have loaded. */
async function showLesson(page: Page, id: string, extra: Record<string, unknown> = {}): Promise<ViewBoxes> {
  await page.evaluate(
    async (lesson, params) => {
      window.oceano.setLesson(lesson);
      if (Object.keys(params).length > 0) window.oceano.setParams(params);
      await window.oceano.loaded();
      // The physics panel has drawn its first measurement (its box is then full size).
      if (window.oceano.getParams().physics) await window.oceano.debug.physicsRuns();
      window.oceano.renderFrame();
    },
    id,
    extra,
  );
  return viewBoxes(page);
}

/** The dividers' lines' centres, and where compareStrips puts the split columns in the free part. */
function dividerCheck(boxes: ViewBoxes, free: Rect): { drawn: number[]; laidOut: number[] } {
  const drawn = boxes.overlays.filter((o) => o.kind === 'compareDivider').map((o) => Math.round(o.box.x + o.box.width / 2));
  const strips = compareStrips(3, 1 / 3, 2 / 3, boxes.canvas.width, free.x, free.x + free.width);
  return { drawn, laidOut: strips.slice(1).map((s) => s.x0) };
}

describe('the free part of the canvas', () => {
  for (const [width, height] of [
    [1366, 768],
    [1280, 720],
    [390, 844],
  ]) {
    // Compare strips, teaching views, plots, captions and labels, where the panel and the drawer leave room
    // (control: the old layout).
    it(`${width} × ${height}: every strip, view, plot, caption and label lies in the room the panels leave`, async () => {
      const { page, consoleErrors } = await openOcean(harness, 't=5&lang=es', width, height);
      const problems: string[] = [];
      const check = (what: string, boxes: ViewBoxes) => {
        const free = measuredFreeArea(boxes);
        for (const [k, v] of Object.entries(free))
          expect(Math.abs(boxes.published[k as keyof Rect] - v), `${what}: published free ${k}`).toBeLessThanOrEqual(1);
        problems.push(...outside(boxes, free).map((p) => `${what}: ${p}`));
        // The lesson card and the panel never cover each other.
        const [drawer, panel] = boxes.panels;
        if (drawer && panel && width > 560) expect(overlaps(drawer, panel), `${what}: card under the panel`).toBe(false);
        return free;
      };

      // Three models with the Fresnel plot and the physics panel open over them.
      let boxes = await showLesson(page, 'compare-models', { fresnelPlot: true, physics: true });
      let free = check('compare', boxes);
      const kinds = new Set(boxes.overlays.map((o) => o.kind));
      for (const kind of ['compareLabel', 'compareDivider', 'fresnelPlot', 'physicsPanel'])
        expect(kinds.has(kind as never), kind).toBe(true);
      const { drawn, laidOut } = dividerCheck(boxes, free);
      drawn.forEach((x, i) => expect(Math.abs(x - laidOut[i]), `divider ${i}`).toBeLessThanOrEqual(1));
      // Each model keeps at least a quarter of the free width in sight (the strips beyond reach under the panels).
      const edges = [free.x, ...laidOut, free.x + free.width];
      for (let i = 0; i + 1 < edges.length; i++) expect(edges[i + 1] - edges[i], `strip ${i}`).toBeGreaterThanOrEqual(free.width / 4);
      // Control: the strips laid over the whole canvas, as before, leave a model a sliver (or nothing) of the free part.
      const old = compareStrips(3, 1 / 3, 2 / 3, boxes.canvas.width).map((s) =>
        Math.max(0, Math.min(s.x1, free.x + free.width) - Math.max(s.x0, free.x)),
      );
      if (width > 560) expect(Math.min(...old), 'old strips').toBeLessThan(free.width / 4);

      // The Perlin stages: the pictures the renderer draws and their captions.
      boxes = await showLesson(page, 'perlin-octaves');
      free = check('perlin', boxes);
      const pictures = figurePictures('noise-octaves', boxes.published);
      for (const { rect } of pictures) expect(contains(free, rect), `picture ${JSON.stringify(rect)}`).toBe(true);
      expect(boxes.overlays.filter((o) => o.kind === 'figureCaption')).toHaveLength(2);
      // Control: the old layout, two squares 0.9 of the canvas's height centred on the canvas.
      const side = 0.9 * height;
      const oldSquare = { x: width / 2 - side - 0.01 * side, y: 0.05 * height, width: side, height: side };
      expect(contains(free, oldSquare)).toBe(false);

      // Labels on the sea: Snell's window, the Kelvin angle, the boat's sample points.
      for (const lesson of ['snell-window', 'kelvin-wake', 'boat-twin']) {
        boxes = await showLesson(page, lesson);
        check(lesson, boxes);
        const labels = boxes.overlays.filter((o) => o.kind === 'lessonLabel');
        console.log(
          `[oceano] ${width}×${height} ${lesson}: ${labels.length} labels in sight, ${labels.map((l) => `"${l.text}" ${Math.round(l.box.x)},${Math.round(l.box.y)}`).join('; ')}`,
        );
        if (lesson === 'snell-window') expect(labels.map((l) => l.text)).toEqual(['48,6°: borde de la ventana de Snell']);
        // Both guide lines named on every screen: on the phone the lines run past the edge and into the sheet at 45 m, where the label first stood (0 in sight then).
        if (lesson === 'kelvin-wake') expect(labels.map((l) => l.text)).toEqual(['19,47° (Kelvin)', '19,47° (Kelvin)']);
      }
      // The sea tools' card, opened from the panel's button as a user does.
      await page.evaluate(() =>
        Array.from(document.querySelectorAll<HTMLButtonElement>('.lil-gui button'))
          .find((b) => /Sea tools|Herramientas/i.test(b.textContent ?? ''))!
          .click(),
      );
      await page.waitForSelector('.oceano-sea-tools:not([hidden])');
      boxes = await viewBoxes(page);
      check('sea tools', boxes);
      expect(boxes.overlays.some((o) => o.kind === 'seaTools')).toBe(true);
      if (width <= 560) {
        // A phone: the open panel, a bottom sheet, takes the lessons' place instead of covering the card.
        await page.click('.lil-gui.lil-root > .lil-title');
        await new Promise((resolve) => setTimeout(resolve, 1000));
        boxes = await showLesson(page, 'compare-models');
        check('phone, panel open', boxes);
        expect(boxes.panels, 'one sheet at a time').toHaveLength(1);
        await page.click('.lil-gui.lil-root > .lil-title');
        await new Promise((resolve) => setTimeout(resolve, 1000));
      }
      expect(problems).toEqual([]);
      expect(consoleErrors).toEqual([]);

      // Control: with the old stylesheet rules the same views put overlays under the panels or past the canvas's edge.
      await addRules(page, OLD_LAYOUT);
      const failing: string[] = [];
      for (const [lesson, extra] of [
        ['compare-models', { fresnelPlot: true, physics: true }],
        ['snell-window', {}],
      ] as const) {
        boxes = await showLesson(page, lesson, extra);
        failing.push(...outside(boxes, measuredFreeArea(boxes)));
      }
      console.log(`[oceano] ${width}×${height} with the old layout: ${failing.join('; ')}`);
      expect(failing.length).toBeGreaterThan(0);
      await page.close();
      // Eight views drawn in SwiftShader, one with the physics panel measuring: minutes on a loaded 2-core machine.
    }, 600_000);
  }
});

describe('inside an <oceano-view>', () => {
  // Control: the old layout.
  it('every overlay and the lesson card lie inside the figure, from 640 × 360 down to 320 × 180', async () => {
    const { page, consoleErrors, violations } = await recordedPage(harness, 1000, 900);
    await page.goto(`${harness.baseUrl}fixtures/no-views.html`, { waitUntil: 'load' });
    await page.evaluate(() => {
      const add = (id: string, width: number, settings: Record<string, string>) => {
        const view = document.createElement('oceano-view');
        view.id = id;
        view.style.width = `${width}px`;
        for (const [name, value] of Object.entries({ t: '3', lang: 'en', ...settings })) view.setAttribute(name, value);
        document.body.append(view);
      };
      add('wide', 640, { lesson: 'fresnel', physics: '1' });
      add('small', 320, { lesson: 'fresnel', physics: '1', compare: 'seed,gerstner' });
      add('figure', 320, { lesson: 'perlin-octaves' });
    });
    await viewsReady(page);
    const measure = async () => {
      const results: Record<string, { box: { width: number; height: number }; card: Rect | null; stray: string[]; kinds: string[] }> = {};
      for (const id of ['wide', 'small', 'figure']) {
        await page.evaluate(async (s) => {
          const view = document.getElementById(s) as HTMLElement & { oceano: typeof window.oceano };
          await view.oceano.loaded();
          if (view.oceano.getParams().physics) await view.oceano.debug.physicsRuns();
          view.oceano.renderFrame();
        }, id);
        const boxes = await viewBoxes(page, `#${id}`);
        // The figure's own box is its canvas's: every overlay, the card included, must lie in it.
        const all = {
          ...boxes,
          overlays: [...boxes.overlays, ...boxes.panels.map((box) => ({ kind: 'lessonLabel' as const, text: 'lesson card', box }))],
        };
        const stray = [...outside(all, boxes.canvas), ...outside(boxes, boxes.published).map((p) => `under the card: ${p}`)];
        results[id] = {
          box: boxes.canvas,
          card: boxes.panels[0] ?? null,
          stray,
          kinds: [...new Set(boxes.overlays.map((o) => o.kind))].sort(),
        };
      }
      return results;
    };
    const results = await measure();
    console.log(`[oceano] figures: ${JSON.stringify(results)}`);
    for (const [id, result] of Object.entries(results)) {
      expect(result.card, id).not.toBeNull();
      expect(result.stray, id).toEqual([]);
    }
    expect(results.wide.kinds).toEqual(['fresnelPlot', 'physicsPanel', 'playButton']);
    expect(results.small.kinds).toEqual(['compareDivider', 'compareLabel', 'fresnelPlot', 'physicsPanel', 'playButton']);
    expect(results.figure.kinds).toEqual(['figureCaption', 'playButton']);
    // A small figure's card starts folded to its lesson's title, the sea in sight; a wide one's open.
    expect(results.small.card!.height).toBeLessThan(50);
    expect(results.wide.card!.height).toBeGreaterThan(200);
    expect(results.small.box).toEqual({ x: 0, y: 0, width: 320, height: 180 });
    expect(consoleErrors).toEqual([]);
    expect(violations.filter((v) => v !== 'script-src-elem inline')).toEqual([]);
    // Control: the old stylesheet rules put the physics panel (370 px wide) past a 320-px figure's edge.
    await addRules(page, OLD_LAYOUT);
    const old = await measure();
    console.log(
      `[oceano] figures with the old layout: ${JSON.stringify(Object.fromEntries(Object.entries(old).map(([id, r]) => [id, r.stray])))}`,
    );
    expect(old.small.stray.length).toBeGreaterThan(0);
    await page.close();
  }, 600_000);
});
