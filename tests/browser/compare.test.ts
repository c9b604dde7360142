import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { compareStrips } from '../../src/sim/compare/compareLayout';
import { differingPixels } from '../support/pictureStatistics';

/**
 * compare=seed,gerstner,fft: every strip of the split view holds exactly the pixels of its
 * model drawn alone on the same camera, wind, seed and time (0 pixels differ), because each
 * model draws its strip with the whole view's projection and a scissor; the dividers are
 * HTML over the canvas, never in it. Negative controls: the strips compared with the wrong
 * models, and with the split moved by 3 px, must differ. One page per model, 320 × 180.
 */
const harness = useHarness();

const WIDTH = 320;
const HEIGHT = 180;
/** Far from the boat (which rides the first model) and looking away from it, so no strip shows it. */
const SHARED = 't=10&seed=1&windSpeed=10&cam=-300,9,40,-300,0,-60';
const MODELS = ['seed', 'gerstner', 'fft'] as const;
const SPLIT = 0.3;
const SPLIT2 = 0.65;

async function picture(page: Page): Promise<PNG> {
  return PNG.sync.read(await canvasPng(page));
}

describe('compare=seed,gerstner,fft: the split view', () => {
  it('holds each model alone, pixel for pixel, on its own strip; wrong models or a split 3 px off fail', async () => {
    const split = await openOcean(
      harness,
      `${SHARED}&compare=seed,gerstner,fft&compareSplit=${SPLIT}&compareSplit2=${SPLIT2}`,
      WIDTH,
      HEIGHT,
    );
    const both = await picture(split.page);
    const splitTriangles = await split.page.evaluate(() => window.oceano.stats().triangles);
    expect(split.consoleErrors).toEqual([]);
    await split.page.close();
    const alone: PNG[] = [];
    const aloneTriangles: number[] = [];
    for (const model of MODELS) {
      const { page, consoleErrors } = await openOcean(harness, `${SHARED}&waves=${model}`, WIDTH, HEIGHT);
      alone.push(await picture(page));
      aloneTriangles.push(await page.evaluate(() => window.oceano.stats().triangles));
      expect(consoleErrors).toEqual([]);
      await page.close();
    }
    const strips = compareStrips(3, SPLIT, SPLIT2, WIDTH);
    expect(strips).toEqual([
      { x0: 0, x1: 96 },
      { x0: 96, x1: 208 },
      { x0: 208, x1: 320 },
    ]);
    const report: string[] = [];
    strips.forEach((strip, i) => {
      const own = differingPixels(both, alone[i], strip.x0, strip.x1);
      report.push(`${MODELS[i]} [${strip.x0}, ${strip.x1}): ${own} px differ from ${MODELS[i]} alone`);
      expect(own, report.at(-1)).toBe(0);
      // Control 1: each strip against the other two models alone (the sides swapped).
      for (let j = 0; j < MODELS.length; j++) {
        if (j === i) continue;
        const wrong = differingPixels(both, alone[j], strip.x0, strip.x1);
        report.push(`  vs ${MODELS[j]} alone: ${wrong} px differ`);
        // Below the horizon nearly every pixel differs; a third of the strip is a loose floor.
        expect(wrong, report.at(-1)).toBeGreaterThan(((strip.x1 - strip.x0) * HEIGHT) / 3);
      }
    });
    // Control 2: the boundaries read 3 px off. The 3 × 180 columns that belong to the
    // neighbour must show up (their sea part, about half of them, differs).
    const off = differingPixels(both, alone[0], 0, strips[0].x1 + 3) + differingPixels(both, alone[1], strips[1].x0 + 3, strips[1].x1 + 3);
    report.push(`split read 3 px right: ${off} px differ`);
    expect(off, report.at(-1)).toBeGreaterThan(2 * 3 * HEIGHT * 0.3);
    // Cost: each model culls its chunks to its strip's frustum, and draws a chunk straddling
    // it as only the tiles (a quarter of a chunk a side) that reach the strip, so the split
    // frame's triangles (all its passes together) stay near one model's, where unculled
    // passes would draw each model's whole frame. Measured here: split 50,101 triangles; alone
    // 43,733 / 44,981 / 45,281 (seed / gerstner / fft), so 1.11 × the largest. Planted faults:
    // whole straddling chunks (no tiles) 62,957 = 1.39 ×; unculled, their sum, about 2.7 ×.
    report.push(`triangles: split ${splitTriangles}, alone ${aloneTriangles.join(' / ')}`);
    console.log(`[oceano] compare strips:\n${report.join('\n')}`);
    expect(splitTriangles, report.at(-1)).toBeLessThan(1.2 * Math.max(...aloneTriangles));
  });

  it('dragging a divider and its arrow keys move compareSplit; the arrows do not steer the boat', async () => {
    const { page, consoleErrors } = await openOcean(harness, `${SHARED}&compare=seed,gerstner&compareSplit=0.5`, WIDTH, HEIGHT);
    const divider = await page.$('.oceano-compare-divider[data-split="compareSplit"]');
    expect(divider).not.toBeNull();
    expect(await page.$$eval('[role="separator"]', (els) => els.length)).toBe(1);
    expect(await divider!.evaluate((el) => [el.getAttribute('aria-valuenow'), el.textContent])).toEqual(['50', 'seedgerstner']);
    const box = (await divider!.boundingBox())!;
    // The line's centre is the split column: 0.5 × 320 = 160 px.
    expect(box.x + box.width / 2).toBe(160);
    await page.mouse.move(box.x + box.width / 2, HEIGHT / 2);
    await page.mouse.down();
    await page.mouse.move(120, HEIGHT / 2, { steps: 4 });
    await page.mouse.move(80, HEIGHT / 2, { steps: 4 });
    await page.mouse.up();
    const dragged = await page.evaluate(() => window.oceano.getParams());
    expect(dragged.compareSplit).toBe(80 / WIDTH);
    expect(await divider!.evaluate((el) => el.getAttribute('aria-valuenow'))).toBe('25');
    // The canvas moved its boundary too: the camera did not orbit (the divider took the drag).
    expect(await page.evaluate(() => window.oceano.getCamera())).toEqual({ position: [-300, 9, 40], target: [-300, 0, -60] });
    await divider!.focus();
    const heading = dragged.boatHeading;
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    await page.evaluate(() => window.oceano.renderFrame());
    const keyed = await page.evaluate(() => window.oceano.getParams());
    expect(keyed.compareSplit).toBeCloseTo(0.27, 12);
    expect(await page.evaluate(() => new URL(window.oceano.shareUrl()).searchParams.get('compareSplit'))).toBe('0.27');
    // The arrows steer the boat while the sea runs (boatSteering.ts): held on a focused divider
    // for 400 ms of running time, they must move only the divider.
    await page.evaluate(() => window.oceano.play());
    await page.keyboard.down('ArrowRight');
    await new Promise((resolve) => setTimeout(resolve, 400));
    await page.keyboard.up('ArrowRight');
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
    await page.evaluate(() => window.oceano.pause());
    const held = await page.evaluate(() => window.oceano.getParams());
    expect(held.compareSplit).toBeCloseTo(0.28, 12);
    expect(held.boatHeading).toBe(heading);
    // Switched at run time: off hides the dividers; another pair rebuilds them with its names.
    await page.evaluate(() => window.oceano.setParams({ compare: 'off' }));
    await page.evaluate(() => window.oceano.renderFrame());
    expect(await page.$eval('.oceano-compare', (el) => (el as HTMLElement).hidden)).toBe(true);
    expect(await page.$$('[role="separator"]')).toHaveLength(0);
    await page.evaluate(() => window.oceano.setParams({ compare: 'gerstner,fft,seed' }));
    await page.evaluate(() => window.oceano.renderFrame());
    expect(await page.$$eval('.oceano-compare-label', (els) => els.map((el) => el.textContent))).toEqual(['gerstner', 'fft', 'seed']);
    expect(await page.$$('[role="separator"]')).toHaveLength(2);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
