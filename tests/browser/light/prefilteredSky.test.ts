import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import type { Page } from 'puppeteer-core';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';

/**
 * The fast path against the slow one: where the sea's unresolved slopes are one number (the
 * seed's), the sky is blurred once into a small cube (src/render/sky/prefilteredSky.ts) and each
 * pixel reads it once; elsewhere each pixel blends two of the sky's mip levels itself. Both
 * must draw the same sea: from the default camera at 640×360, the sea's rows (below the
 * horizon) differ by at most a level, before and after the sun moves, which repaints
 * the sky. The cube is not painted again while the clock runs (the seed's roughness moves by
 * thousandths of a mip level a second). Control: a cube that ignores the moved sun keeps the
 * old sky in the sea.
 */
const harness = useHarness();
const SEA_ROWS = [170, 360] as const;
/** Measured: 0.06–0.10 levels mean, 1 at most (SwiftShader); the bounds sit just above. */
const MEAN_BOUND = 0.15;
const MAX_BOUND = 2;

interface Difference {
  mean: number;
  max: number;
}

function seaDifference(a: Buffer, b: Buffer): Difference {
  const imageA = PNG.sync.read(a);
  const imageB = PNG.sync.read(b);
  let sum = 0;
  let max = 0;
  let count = 0;
  for (let y = SEA_ROWS[0]; y < SEA_ROWS[1]; y++) {
    for (let x = 0; x < imageA.width; x++) {
      const i = (y * imageA.width + x) * 4;
      for (let c = 0; c < 3; c++, count++) {
        const d = Math.abs(imageA.data[i + c] - imageB.data[i + c]);
        sum += d;
        max = Math.max(max, d);
      }
    }
  }
  return { mean: sum / count, max };
}

/** The frame with the prefiltered sky and the frame with the per-pixel blend, as they are now. */
async function bothWays(page: Page): Promise<Difference> {
  const shot = async (prefiltered: boolean) => {
    await page.evaluate(async (on) => {
      await window.oceano.debug.setShadingFixes({ prefilteredSky: on });
      window.oceano.renderFrame();
    }, prefiltered);
    return canvasPng(page);
  };
  const fast = await shot(true);
  const slow = await shot(false);
  await page.evaluate(() => window.oceano.debug.setShadingFixes({ prefilteredSky: true }));
  return seaDifference(fast, slow);
}

const say = (d: Difference) => `mean ${d.mean.toFixed(3)}, max ${d.max} levels`;

describe('the sky prefiltered for a sea of one roughness', () => {
  // And the sky is not painted every frame.
  it('draws what the per-pixel blend of two mip levels draws, after the sun moves too', async () => {
    const { page } = await openOcean(harness, 't=10', 640, 360);
    await page.evaluate(() => window.oceano.pause());
    const first = await bothWays(page);
    await page.evaluate(() => window.oceano.setParams({ sunElevation: 12, sunAzimuth: 150 }));
    const movedSun = await bothWays(page);
    const paints = await page.evaluate(async () => {
      const before = await window.oceano.debug.prefilteredSkyPaints();
      for (let k = 1; k <= 60; k++) {
        window.oceano.setTime(10 + k / 60);
        window.oceano.renderFrame();
      }
      return { before, after: await window.oceano.debug.prefilteredSkyPaints() };
    });
    const report = `first ${say(first)}; after the sun moved ${say(movedSun)}; paints ${paints.before} → ${paints.after} over 60 frames`;
    console.log(`[oceano] prefilteredSky ${report}`);
    expect(first.mean, report).toBeLessThan(MEAN_BOUND);
    expect(first.max, report).toBeLessThanOrEqual(MAX_BOUND);
    expect(movedSun.mean, report).toBeLessThan(MEAN_BOUND);
    expect(movedSun.max, report).toBeLessThanOrEqual(MAX_BOUND);
    expect(paints.before, report).toBeGreaterThan(0);
    expect(paints.after - paints.before, report).toBeLessThanOrEqual(1);
    await page.close();
  });

  it('control: a prefiltered sky that does not follow the sun fails the comparison', async () => {
    const { page } = await openOcean(harness, 't=10', 640, 360);
    await page.evaluate(async () => {
      window.oceano.pause();
      await window.oceano.debug.setShadingFixes({ prefilterFollowsSun: false });
      window.oceano.setParams({ sunElevation: 12, sunAzimuth: 150 });
    });
    const stale = await bothWays(page);
    console.log(`[oceano] prefilteredSky control (stale sun): ${say(stale)}`);
    expect(stale.mean).toBeGreaterThan(MEAN_BOUND);
    await page.close();
  });
});
