import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer-core';
import { openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { foamDriftTexels, foamDriftVelocity } from '../../../src/sim/waves/fft/foamDrift';
import { foamLatticeIndex } from '../../../src/sim/waves/fft/foamMemory';

/**
 * The foam left behind drifts downwind with the surface (src/sim/waves/fft/foamDrift.ts), on
 * the GPU as in its TS twin: the remembered foam's tile at t and at t + 4 s, read back, matches
 * best when shifted by the drift's whole texels (3 % of 10 m/s for 4 s: 1.2 m, 5 texels of
 * 0.26 m), the wind blowing towards +x. τ = 8 s, so that foam laid before t is still there at
 * t + 4 s. Control: the foam that does not drift matches best where it lay.
 */
const harness = useHarness();
const WIND = { windSpeed: 10, windDirection: 90 };
const QUERY = `waves=fft&windSpeed=${WIND.windSpeed}&windDirection=${WIND.windDirection}&foamFade=8&t=20`;
const [FROM, TO] = [20, 24];
const SEARCH = 8;

type Memory = { n: number; texel: number; data: number[] };

async function memoryAt(page: Page, time: number): Promise<Memory> {
  await page.evaluate((t) => {
    window.oceano.pause();
    window.oceano.setTime(t);
  }, time);
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const memory = await page.evaluate(() => window.oceano.debug.foamMemory());
  if (!memory) throw new Error('the FFT sea gave no foam memory');
  return memory;
}

/** The shift (x, z), in texels, at which the later tile best matches the earlier one: the peak of their cross-covariance. */
function bestShift(before: Memory, after: Memory): [number, number] {
  const n = before.n;
  const mean = (d: number[]) => d.reduce((s, v) => s + v, 0) / d.length;
  const [a, b] = [before.data, after.data];
  const [ma, mb] = [mean(a), mean(b)];
  let best = { covariance: -Infinity, shift: [0, 0] as [number, number] };
  for (let sz = -SEARCH; sz <= SEARCH; sz++) {
    for (let sx = -SEARCH; sx <= SEARCH; sx++) {
      let covariance = 0;
      for (let z = 0; z < n; z++) {
        const row = ((z + sz + n) % n) * n;
        for (let x = 0; x < n; x++) covariance += (a[z * n + x] - ma) * (b[row + ((x + sx + n) % n)] - mb);
      }
      if (covariance > best.covariance) best = { covariance, shift: [sx, sz] };
    }
  }
  return best.shift;
}

async function measuredShift(drifts: boolean): Promise<{ shift: [number, number]; texel: number }> {
  const { page } = await openOcean(harness, QUERY, 320, 180);
  if (!drifts) await page.evaluate(() => window.oceano.debug.setShadingFixes({ foamDrift: false }));
  const before = await memoryAt(page, FROM);
  const after = await memoryAt(page, TO);
  await page.close();
  expect(before.data.filter((p) => p > 0).length, 'foam remembered at t').toBeGreaterThan(100);
  return { shift: bestShift(before, after), texel: before.texel };
}

describe('the foam left behind drifts with the surface', () => {
  // Control: without the drift, where it lay.
  it('the GPU memory 4 s later matches best shifted by the drift’s whole texels downwind', { timeout: 120_000 }, async () => {
    const { shift, texel } = await measuredShift(true);
    const velocity = foamDriftVelocity(WIND);
    const [x1, z1] = foamDriftTexels(velocity, texel, foamLatticeIndex(TO));
    const [x0, z0] = foamDriftTexels(velocity, texel, foamLatticeIndex(FROM));
    const expected = [x1 - x0, z1 - z0];
    const control = await measuredShift(false);
    console.log(
      `[oceano] foam drift over ${TO - FROM} s: best shift ${shift.join(', ')} texels of ${texel.toFixed(3)} m (expected ${expected.join(', ')}); control ${control.shift.join(', ')}`,
    );
    expect(shift).toEqual(expected);
    expect(expected[0]).toBeGreaterThanOrEqual(4);
    expect(control.shift).toEqual([0, 0]);
  });
});
