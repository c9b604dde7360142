import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { recordedPage, viewsReady } from './pages';
import { LESSONS, lessonView } from '../../src/app/lessons/lessonCatalog';
import { LESSON_TITLES } from '../../src/app/lessons/lessonOutline';
import { quoteMatchesFile } from '../../src/app/lessons/quoteExtraction';
import { PerspectiveCamera, Vector3 } from 'three';
import { hullSamplePoints } from '../../src/sim/boat/boatPose';

const harness = useHarness();
const root = join(import.meta.dirname, '..', '..');

/** What the open card shows, read from the page. */
function cardFacts(page: Page) {
  return page.evaluate(() => {
    const card = document.querySelector('.oceano-lesson-card') as HTMLElement;
    const file = card.querySelector('.oceano-lesson-code-file')!.textContent!;
    return {
      lesson: window.oceano.lesson(),
      shown: !card.hidden && card.getBoundingClientRect().height > 0,
      title: card.querySelector('.oceano-lesson-title')!.textContent,
      maths: card.querySelectorAll('.oceano-lesson-math math').length,
      mathHeight: (card.querySelector('.oceano-lesson-math math') as Element).getBoundingClientRect().height,
      file,
      code: card.querySelector('.oceano-lesson-code-text')!.textContent!,
      controls: card.querySelectorAll('.oceano-lesson-control').length,
      notices: window.oceano.notices(),
      focusRing: getComputedStyle(document.activeElement!).outlineStyle,
    };
  });
}

/**
 * The widest share of the canvas left free by the overlays: across (columns no overlay
 * covers) and down (rows no overlay covers), each as a fraction of the canvas's size.
 */
function freeShare(page: Page) {
  return page.evaluate(() => {
    const canvas = document.querySelector('canvas')!.getBoundingClientRect();
    const boxes = Array.from(document.querySelectorAll<HTMLElement>('.oceano-lessons, .lil-gui.lil-root'))
      .filter((el) => el.offsetParent !== null)
      .map((el) => el.getBoundingClientRect());
    const widestGap = (spans: [number, number][], start: number, end: number) => {
      let gap = 0;
      let at = start;
      for (const [a, b] of spans.sort((p, q) => p[0] - q[0])) {
        gap = Math.max(gap, a - at);
        at = Math.max(at, b);
      }
      return Math.max(gap, end - at);
    };
    return {
      across:
        widestGap(
          boxes.map((r) => [r.left, r.right]),
          canvas.left,
          canvas.right,
        ) / canvas.width,
      down:
        widestGap(
          boxes.map((r) => [r.top, r.bottom]),
          canvas.top,
          canvas.bottom,
        ) / canvas.height,
      drawerAtBottom: Math.abs(document.querySelector('.oceano-lessons')!.getBoundingClientRect().bottom - canvas.bottom) < 1,
    };
  });
}

/** The panel as it was before lessons: top right at its full height, every folder open. */
const OLD_PANEL = `#oceano-page > .lil-gui.lil-root { top: 0 !important; bottom: auto !important; left: auto !important; right: 12px !important; width: 245px !important; max-height: 100% !important; }`;

describe('lessons', () => {
  // Each card with MathML and the quote equal to its file, no notice, focus visible.
  it('a keyboard walk opens every lesson in order, each with its view and its card', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=2', 1366, 768);
    await page.waitForSelector('.oceano-lessons-open');
    // Tab reaches the list; Enter opens the first lesson, then → walks on.
    await page.focus('.oceano-lessons-open');
    await page.keyboard.press('Enter');
    for (const [index, lesson] of LESSONS.entries()) {
      if (index > 0) await page.keyboard.press('ArrowRight');
      const facts = await cardFacts(page);
      expect(facts.lesson).toBe(lesson.id);
      expect(facts.shown, lesson.id).toBe(true);
      expect(facts.title).toBe(LESSON_TITLES[lesson.id].en);
      expect(facts.maths, lesson.id).toBeGreaterThan(0);
      expect(facts.mathHeight, lesson.id).toBeGreaterThan(10);
      expect(facts.notices, lesson.id).toEqual([]);
      expect(facts.controls).toBeGreaterThan(0);
      expect(facts.focusRing).toBe('solid');
      const [, file, first, last] = /^(.+):(\d+)–(\d+)$/.exec(facts.file)!;
      const quote = { file, firstLine: Number(first), lastLine: Number(last), text: facts.code };
      expect(quoteMatchesFile(quote, readFileSync(join(root, file), 'utf8')), lesson.id).toBe(true);
      const view = lessonView(lesson);
      expect(await page.evaluate(() => window.oceano.getParams())).toEqual(view.params);
      const camera = await page.evaluate(() => window.oceano.getCamera());
      camera.position.forEach((c, i) => expect(c).toBeCloseTo(view.camera.position[i], 6));
    }
    // Control: a quote one line off no longer equals its file.
    const facts = await cardFacts(page);
    const [, file, first, last] = /^(.+):(\d+)–(\d+)$/.exec(facts.file)!;
    expect(
      quoteMatchesFile(
        { file, firstLine: Number(first) + 1, lastLine: Number(last) + 1, text: facts.code },
        readFileSync(join(root, file), 'utf8'),
      ),
    ).toBe(false);
    // ← walks back.
    await page.keyboard.press('ArrowLeft');
    expect(await page.evaluate(() => window.oceano.lesson())).toBe(LESSONS.at(-2)!.id);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  // An unknown id gives a notice that changes nothing.
  it('API and URL: lessons() in the page’s language, ?lesson= and share links, an unknown id', async () => {
    const { page } = await openOcean(harness, 'lesson=fresnel&lang=es', 800, 600);
    await page.waitForSelector('.oceano-lesson-card:not([hidden])');
    const list = await page.evaluate(() => window.oceano.lessons());
    expect(list.length).toBe(LESSONS.length);
    expect(list[0]).toEqual({
      id: 'flat-plane',
      title: LESSON_TITLES['flat-plane'].es,
      section: 'Superficie del agua',
      question: true,
      exercise: false,
    });
    expect(await page.evaluate(() => window.oceano.lesson())).toBe('fresnel');
    expect(await page.evaluate(() => new URL(window.oceano.shareUrl()).searchParams.get('lesson'))).toBe('fresnel');
    const before = await page.evaluate(() => ({ params: window.oceano.getParams(), camera: window.oceano.getCamera() }));
    expect(await page.evaluate(() => window.oceano.setLesson('no-such-lesson'))).toBe(false);
    const after = await page.evaluate(() => ({
      params: window.oceano.getParams(),
      camera: window.oceano.getCamera(),
      lesson: window.oceano.lesson(),
      notices: window.oceano.notices(),
    }));
    expect(after.params).toEqual(before.params);
    expect(after.camera).toEqual(before.camera);
    expect(after.lesson).toBe('fresnel');
    expect(after.notices).toHaveLength(1);
    expect(after.notices[0]).toMatch(/^No existe la lección "no-such-lesson"/);
    expect(await page.evaluate(() => window.oceano.setLesson('gale' as string))).toBe(false);
    expect(await page.evaluate(() => window.oceano.setLesson('fft-gale'))).toBe(true);
    expect(await page.evaluate(() => window.oceano.getParams().windSpeed)).toBe(20);
    await page.close();
  });

  // Control: a wide card fails.
  it('laptop 1366×768: the panel and the card leave at least 60 % of the canvas free across', async () => {
    const { page } = await openOcean(harness, 'lesson=lod-bands', 1366, 768);
    await page.waitForSelector('.oceano-lesson-card:not([hidden])');
    await page.waitForSelector('.lil-gui.lil-root');
    const free = await freeShare(page);
    expect(free.across).toBeGreaterThanOrEqual(0.6);
    // Folders start folded, except the lesson's (LOD & culling).
    const open = await page.evaluate(() =>
      Array.from(document.querySelectorAll('.lil-gui.lil-root .lil-gui:not(.lil-closed) > .lil-title'), (t) => t.textContent),
    );
    expect(open).toEqual(['LOD & culling']);
    await page.addStyleTag({ content: '#oceano-page .oceano-lessons { width: 340px; }' });
    expect((await freeShare(page)).across).toBeLessThan(0.6);
    await page.close();
  });

  // Control: the old panel fails.
  it('phone 390×844: the card and the open panel are bottom sheets, the sea visible above', async () => {
    const { page } = await openOcean(harness, 'lesson=normals-right&lang=es', 390, 844);
    await page.waitForSelector('.oceano-lesson-card:not([hidden])');
    await page.waitForSelector('.lil-gui.lil-root');
    let free = await freeShare(page);
    expect(free.drawerAtBottom).toBe(true);
    expect(free.down).toBeGreaterThanOrEqual(0.5);
    await page.click('.lil-gui.lil-root > .lil-title');
    free = await freeShare(page);
    expect(free.down).toBeGreaterThanOrEqual(0.5);
    await page.addStyleTag({ content: OLD_PANEL });
    await page.evaluate(() =>
      document.querySelectorAll<HTMLElement>('.lil-gui.lil-root .lil-gui.lil-closed > .lil-title').forEach((title) => title.click()),
    );
    // lil-gui unfolds a folder with a 300 ms transition of its height, begun on a later frame.
    await new Promise((resolve) => setTimeout(resolve, 1000));
    free = await freeShare(page);
    expect(free.down).toBeLessThan(0.5);
    expect(free.across).toBeLessThan(0.6);
    await page.close();
  });

  // Control: the hull turned round.
  it('the boat lessons mark the five points the CPU twin samples, on the hull and following it', async () => {
    const width = 1366;
    const height = 768;
    const { page, consoleErrors } = await openOcean(harness, 'lesson=boat-twin&t=5', width, height);
    await page.waitForSelector('.oceano-lesson-label-hullPoints:not([hidden])');
    /** The dots' centres on the page, by name, and where the twin's sample points project. */
    const measure = async () => {
      await page.evaluate(() => window.oceano.renderFrame());
      const facts = await page.evaluate(() => ({
        dots: Array.from(document.querySelectorAll<HTMLElement>('.oceano-lesson-label-hullPoints'), (label) => {
          const r = label.getBoundingClientRect();
          // The dot sits 5 px inside the label's left end, or its right end when the name is written leftwards.
          const x = label.classList.contains('oceano-lesson-label-leftwards') ? r.right - 5 : r.left + 5;
          return { name: label.textContent, hidden: label.hidden, x, y: r.top + r.height / 2 };
        }),
        boat: window.oceano.boat(),
        camera: window.oceano.getCamera(),
        legend: document.querySelector('.oceano-lesson-legend')?.textContent ?? '',
      }));
      const camera = new PerspectiveCamera(55, width / height, 0.1, 1000);
      camera.position.fromArray(facts.camera.position);
      camera.lookAt(...facts.camera.target);
      camera.updateMatrixWorld();
      const project = async (heading: number) => {
        const points = hullSamplePoints(facts.boat.position[0], facts.boat.position[2], heading, facts.boat.hull);
        const out: Record<string, [number, number]> = {};
        for (const [name, [x, z]] of Object.entries(points)) {
          const y = await page.evaluate((px, pz) => window.oceano.sampleSurface(px, pz).height, x, z);
          const p = new Vector3(x, y, z).project(camera);
          out[name] = [((p.x + 1) / 2) * width, ((1 - p.y) / 2) * height];
        }
        return out;
      };
      return { ...facts, projected: await project(facts.boat.heading), turned: await project(facts.boat.heading + Math.PI) };
    };
    const names = ['centre', 'bow', 'stern', 'port', 'starboard'];
    const worst = (facts: Awaited<ReturnType<typeof measure>>, which: 'projected' | 'turned') =>
      Math.max(...facts.dots.map((dot, i) => Math.hypot(dot.x - facts[which][names[i]][0], dot.y - facts[which][names[i]][1])));
    let facts = await measure();
    expect(facts.dots.map((d) => d.name)).toEqual(names);
    expect(facts.dots.every((d) => !d.hidden)).toBe(true);
    for (const name of names) expect(facts.legend).toContain(name);
    expect(worst(facts, 'projected')).toBeLessThan(0.75);
    expect(worst(facts, 'turned')).toBeGreaterThan(20);
    // They follow the boat: turned by 90° and a second later, the dots are where its new points are.
    await page.evaluate(() => {
      window.oceano.setParams({ boatHeading: 90 });
      window.oceano.setTime(6);
    });
    facts = await measure();
    console.log(
      `[oceano] hull sample points: worst ${worst(facts, 'projected').toFixed(2)} px from their projections; with the hull turned round ${worst(facts, 'turned').toFixed(1)} px`,
    );
    expect(worst(facts, 'projected')).toBeLessThan(0.75);
    expect(worst(facts, 'turned')).toBeGreaterThan(20);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  // The card and the Fresnel plot lie inside the figure’s box.
  it('<oceano-view lesson="fresnel">: the card and the plot inside the figure; the attribute changes the lesson', async () => {
    const { page, violations } = await recordedPage(harness, 900, 700);
    await page.goto(`${harness.baseUrl}fixtures/two-views.html`, { waitUntil: 'load' });
    await viewsReady(page);
    await page.evaluate(() => {
      const view = document.createElement('oceano-view');
      view.id = 'lesson';
      view.setAttribute('lesson', 'fresnel');
      view.setAttribute('t', '3');
      view.style.width = '640px';
      document.body.prepend(view);
    });
    await viewsReady(page);
    await page.waitForSelector('#lesson .oceano-lesson-card:not([hidden])');
    // The plot's code is fetched when the lesson first asks for it.
    await page.waitForSelector('#lesson .oceano-fresnel-plot');
    const inside = () =>
      page.evaluate(() => {
        const box = document.getElementById('lesson')!.getBoundingClientRect();
        const within = (selector: string) => {
          const r = document.querySelector(`#lesson ${selector}`)!.getBoundingClientRect();
          return r.width > 0 && r.left >= box.left && r.right <= box.right && r.top >= box.top && r.bottom <= box.bottom;
        };
        return {
          card: within('.oceano-lessons'),
          plot: within('.oceano-fresnel-plot'),
          list: document.querySelectorAll('#lesson .oceano-lessons-open').length,
        };
      });
    expect(await inside()).toEqual({ card: true, plot: true, list: 0 });
    await page.evaluate(() => document.getElementById('lesson')!.setAttribute('lesson', 'normals-right'));
    expect(
      await page.evaluate(() => (document.getElementById('lesson') as HTMLElement & { oceano: { lesson(): string } }).oceano.lesson()),
    ).toBe('normals-right');
    // The fixture's strict CSP (no inline styles): the card's styles and labels break none of it
    // (the fixture's own inline script is refused on purpose).
    expect(violations.filter((v) => v !== 'script-src-elem inline')).toEqual([]);
    await page.close();
  });
});
