import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import pixelmatch from 'pixelmatch';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';

/**
 * The foam left behind is stepped on a lattice of simulation times, never per frame
 * (src/sim/waves/fft/foamMemory.ts): stepping frame by frame to t and jumping straight to t
 * draw the same foam, pixel for pixel. Control: the frame one step of 1/60 s later differs.
 */
const harness = useHarness();
const QUERY = 'waves=fft&windSpeed=15&t=20&cam=0,40,0,0,0,-30';
const SIZE = { width: 480, height: 270 };
const STEPS = 45;

function differing(a: Buffer, b: Buffer): number {
  const [pa, pb] = [a, b].map((png) => PNG.sync.read(png));
  return pixelmatch(pa.data, pb.data, undefined, SIZE.width, SIZE.height, { threshold: 0 });
}

describe('foam in simulation time', () => {
  // Control: one step later differs.
  it(`${STEPS} steps of 1/60 s from t = 20 s draw what a jump to the same t draws, pixel for pixel`, { timeout: 240_000 }, async () => {
    const stepped = await openOcean(harness, QUERY, SIZE.width, SIZE.height);
    const time = await stepped.page.evaluate((steps) => {
      window.oceano.pause();
      for (let i = 0; i < steps; i++) window.oceano.step();
      return Number(new URL(window.oceano.shareUrl()).searchParams.get('t'));
    }, STEPS);
    expect(time).toBeCloseTo(20 + STEPS / 60, 9);
    const afterSteps = await canvasPng(stepped.page);
    await stepped.page.close();

    const jumped = await openOcean(harness, QUERY, SIZE.width, SIZE.height);
    await jumped.page.evaluate((t) => {
      window.oceano.pause();
      window.oceano.setTime(t);
    }, time);
    const afterJump = await canvasPng(jumped.page);
    await jumped.page.evaluate((t) => window.oceano.setTime(t + 1 / 60), time);
    const oneStepLater = await canvasPng(jumped.page);
    await jumped.page.close();

    expect(differing(afterSteps, afterJump)).toBe(0);
    expect(differing(afterJump, oneStepLater)).toBeGreaterThan(0.005 * SIZE.width * SIZE.height);
  });
});
