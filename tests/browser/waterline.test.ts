import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';

const harness = useHarness();

/**
 * Spots away from the boat (which lies near the origin), each seen from 5 cm above the
 * surface there, looking level along −z. At t=10 the near plane (0.5 m out) crosses the
 * water at both: the frame is 'straddling' and goes through the per-pixel waterline.
 */
const SPOTS: readonly [number, number][] = [[300, 300], [20, 0]];
const EYE_CLEARANCE = 0.05;
// Measured at 640 × 360: 0 and 0 with the sand marked as under the water, 2411 and 2272
// without (main). Another spot, (37, 0), showed 22 along a rim at the waterline with the mark.
const MAX_SPARKLE_PIXELS = 50;

/**
 * Bright green outliers in the lower half of the frame: green above 150 and more than 60
 * over red. The water's fog and the sky never come near (their green stays under 130); the
 * unfogged, caustic-lit sand the fault showed does.
 */
function sparklePixels(png: Buffer): number {
  const { width, height, data } = PNG.sync.read(png);
  let count = 0;
  for (let y = Math.floor(height / 2); y < height; y++) {
    for (let x = 0; x < width; x++) {
      const o = (y * width + x) * 4;
      if (data[o + 1] > 150 && data[o + 1] > data[o] + 60) count++;
    }
  }
  return count;
}

async function viewFromJustAbove(page: Page, x: number, z: number): Promise<{ png: Buffer; submersion: string }> {
  const submersion = await page.evaluate(async (x, z, clearance) => {
    const eyeY = window.oceano.sampleSurface(x, z).height + clearance;
    window.oceano.setCamera({ position: [x, eyeY, z], target: [x, eyeY, z - 100] });
    window.oceano.renderFrame();
    await window.oceano.loaded();
    window.oceano.renderFrame();
    return window.oceano.stats().submersion;
  }, x, z, EYE_CLEARANCE);
  return { png: await canvasPng(page), submersion };
}

describe('the waterline seen from just above the water', () => {
  it('draws no band of bright sand along the waterline with the camera 5 cm up', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=10', 640, 360);
    await page.evaluate(() => window.oceano.pause());
    const fixed: number[] = [];
    for (const [x, z] of SPOTS) {
      const { png, submersion } = await viewFromJustAbove(page, x, z);
      expect(submersion).toBe('straddling');
      fixed.push(sparklePixels(png));
    }
    // Negative control, and main's picture: the sand not marked as under the water.
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ seaBedMark: false }));
    const unmarked: number[] = [];
    for (const [x, z] of SPOTS) unmarked.push(sparklePixels((await viewFromJustAbove(page, x, z)).png));
    console.log(`[oceano] sparkle pixels 5 cm up: fixed ${fixed.join(', ')}; sand unmarked ${unmarked.join(', ')}`);
    for (const count of fixed) expect(count).toBeLessThan(MAX_SPARKLE_PIXELS);
    for (const count of unmarked) expect(count).toBeGreaterThan(MAX_SPARKLE_PIXELS);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
