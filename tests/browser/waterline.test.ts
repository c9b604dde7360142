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
const SPOTS: readonly [number, number][] = [
  [300, 300],
  [20, 0],
];
const EYE_CLEARANCE = 0.05;
// Measured at 640 × 360: 0 and 0 with the near plane fitted (no sea bed drawn), 0 and 0
// with the 0.5 m near plane and the sand marked as under the water, 249 and 73 unmarked
// (2411 and 2272 before ocean.vert's w = 0 guard filled the hole before the eye, which
// showed more sand). Another spot, (37, 0), showed 22 along a rim at the waterline with the mark.
const MAX_SPARKLE_PIXELS = 50;
/**
 * Bound on the distance (RGB levels) between the mean colour of the bottom quarter seen
 * from 5 or 30 cm up and from 0.6 m up at the same spot. Measured at 320 × 180: 3.4, 3.3,
 * 1.9, 0.5 with the near plane fitted; 73 and 66 at 5 cm with the fixed 0.5 m near plane
 * (the view from inside the water), 3.3 and 0.5 at 30 cm (the clipped rows lie lower).
 */
const MAX_LOWER_FRAME_DISTANCE = 10;

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

async function viewFromJustAbove(
  page: Page,
  x: number,
  z: number,
  clearance = EYE_CLEARANCE,
): Promise<{ png: Buffer; submersion: string }> {
  const submersion = await page.evaluate(
    async (x, z, clearance) => {
      const eyeY = window.oceano.sampleSurface(x, z).height + clearance;
      window.oceano.setCamera({ position: [x, eyeY, z], target: [x, eyeY, z - 100] });
      // This frame asks for any part the view needs (the underwater passes); loaded() draws
      // again once they are there, and that frame's stats are read (canvasPng draws the picture).
      window.oceano.renderFrame();
      await window.oceano.loaded();
      return window.oceano.stats().submersion;
    },
    x,
    z,
    clearance,
  );
  return { png: await canvasPng(page), submersion };
}

describe('the waterline seen from just above the water', () => {
  it('draws no band of bright sand along the waterline with the camera 5 cm up', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=10', 640, 360);
    await page.evaluate(() => window.oceano.pause());
    // With the near plane fitted to the eye's clearance (src/render/ocean/nearPlane.ts) the frame is
    // drawn from above and the sea bed is not drawn at all.
    const fitted: number[] = [];
    for (const [x, z] of SPOTS) {
      const { png, submersion } = await viewFromJustAbove(page, x, z);
      expect(submersion).toBe('above');
      fitted.push(sparklePixels(png));
    }
    // The sea bed's mark matters wherever the near plane does cross the water (an eye within
    // the near plane's 1 cm floor, a steep crest): the fixed 0.5 m near plane makes it cross here.
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ clearanceNear: false }));
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
    console.log(
      `[oceano] sparkle pixels 5 cm up: near fitted ${fitted.join(', ')}; near 0.5 m ${fixed.join(', ')}; sand unmarked ${unmarked.join(', ')}`,
    );
    for (const count of [...fitted, ...fixed]) expect(count).toBeLessThan(MAX_SPARKLE_PIXELS);
    for (const count of unmarked) expect(count).toBeGreaterThan(MAX_SPARKLE_PIXELS);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});

/**
 * Spots for the lower frame: (300, 300) puts the eye's plane on a grid row (its vertices at
 * clip w = 0, see ocean.vert), (301, 299.3) does not. The surface falls ahead of both.
 */
const LOW_SPOTS: readonly [number, number][] = [
  [300, 300],
  [301, 299.3],
];
const LOW_CLEARANCES = [0.05, 0.3];

/** Mean colour of the bottom quarter of the frame, where a level eye looks 20-27° down. */
function bottomQuarterMean(png: Buffer): [number, number, number] {
  const { width, height, data } = PNG.sync.read(png);
  const sum = [0, 0, 0];
  const from = Math.floor((height * 3) / 4);
  for (let y = from; y < height; y++) {
    for (let x = 0; x < width; x++) for (let c = 0; c < 3; c++) sum[c] += data[(y * width + x) * 4 + c];
  }
  const n = (height - from) * width;
  return [sum[0] / n, sum[1] / n, sum[2] / n];
}

const colourDistance = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

describe('the lower frame seen from just above the water', () => {
  it('shows the surface from above, not the view from inside the water, with the eye 5 cm and 30 cm up', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=10', 320, 180);
    await page.evaluate(() => window.oceano.pause());
    const measure = async () => {
      const rows: { submersion: string; distance: number }[] = [];
      for (const [x, z] of LOW_SPOTS) {
        // From 0.6 m up the near plane (0.5 m) is clear of the water: the surface from above.
        const above = bottomQuarterMean((await viewFromJustAbove(page, x, z, 0.6)).png);
        for (const clearance of LOW_CLEARANCES) {
          const { png, submersion } = await viewFromJustAbove(page, x, z, clearance);
          rows.push({ submersion, distance: colourDistance(bottomQuarterMean(png), above) });
        }
      }
      return rows;
    };
    const fixed = await measure();
    // Negative control, and main's picture: the fixed 0.5 m near plane.
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ clearanceNear: false }));
    const fixedNear = await measure();
    console.log(
      `[oceano] lower frame 5 / 30 cm up, colour distance to 0.6 m up: near fitted ${JSON.stringify(fixed)}; near 0.5 m ${JSON.stringify(fixedNear)}`,
    );
    for (const row of fixed) {
      expect(row.submersion).toBe('above');
      expect(row.distance).toBeLessThan(MAX_LOWER_FRAME_DISTANCE);
    }
    expect(fixedNear.some((row) => row.distance > MAX_LOWER_FRAME_DISTANCE)).toBe(true);
    for (const row of fixedNear) expect(row.submersion).not.toBe('above');
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
