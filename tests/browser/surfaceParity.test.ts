import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { openWithNativeSin, PARITY_LIMITS } from './parity';
import { seededRandom } from '../../src/sim/noise/integerHash';

/**
 * The CPU twin against the real shader, far from the origin and late in time: the cases
 * where float32 on the GPU would drift from the CPU's doubles if a phase or a tile offset
 * were not reduced before it reached the shader.
 */
const PARITY_SEED = 20261121;
const TIMES = [0, 37.25, 4321.5, 100_000.125, 987_654.3];
const POINTS_PER_TIME = 256;
const EXTENT = 3000;

const harness = useHarness();

/** The defaults, and the steepest, shortest swell the parameters allow: the hardest case for float32. */
const CASES = [
  { query: 'seed=9&t=0', limits: PARITY_LIMITS.defaults },
  { query: 'seed=4&t=0&swellAmplitude=4&swellFrequency=0.2&rippleStrength=2', limits: PARITY_LIMITS.steepest },
];

type Case = { t: number; points: [number, number][] };

function parityCases(): Case[] {
  const random = seededRandom(PARITY_SEED);
  // The GPU receives positions as float32, as every ocean vertex is: the points are chosen
  // on that lattice so both sides evaluate the very same (x, z).
  return TIMES.map((t) => ({
    t,
    points: Array.from(
      { length: POINTS_PER_TIME },
      () => [Math.fround((random() * 2 - 1) * EXTENT), Math.fround((random() * 2 - 1) * EXTENT)] as [number, number],
    ),
  }));
}

function worstDisagreement(page: Page, cases: Case[]) {
  return page.evaluate(async (cases) => {
    const o = window.oceano;
    o.pause();
    let height = 0;
    let normal = 0;
    let at = { x: 0, z: 0, t: 0 };
    for (const { t, points } of cases) {
      o.setTime(t);
      const gpu = await o.probeGpu(points, t);
      points.forEach(([x, z], i) => {
        const cpu = o.sampleSurface(x, z);
        const dh = Math.abs(cpu.height - gpu[i].height);
        if (dh > height) at = { x, z, t };
        height = Math.max(height, dh);
        for (let c = 0; c < 3; c++) normal = Math.max(normal, Math.abs(cpu.normal[c] - gpu[i].normal[c]));
      });
    }
    return { height, normal, at };
  }, cases);
}

describe('CPU twin vs GPU shader', () => {
  // TIMES.length × POINTS_PER_TIME random points (seed PARITY_SEED), |x| and |z| up to EXTENT m,
  // t up to 1e6 s.
  it.each(CASES)('agrees within $limits.height m and $limits.normal in the normal on seeded points: $query', async ({ query, limits }) => {
    const cases = parityCases();
    const farPoints = cases.flatMap((c) => c.points).filter(([x, z]) => Math.abs(x) >= 2000 && Math.abs(z) >= 2000).length;
    expect(farPoints).toBeGreaterThan(50);
    const { page } = await openOcean(harness, query);
    const worst = await worstDisagreement(page, cases);
    console.log(
      `[oceano] CPU–GPU parity (${query}): max |Δheight| = ${worst.height.toExponential(2)} m at (${worst.at.x}, ${worst.at.z}, t=${worst.at.t}), max |Δnormal| = ${worst.normal.toExponential(2)}`,
    );
    expect(worst.height).toBeLessThan(limits.height);
    expect(worst.normal).toBeLessThan(limits.normal);
    await page.close();
  });

  it("rejects the driver's own sin in the swell (negative control: the Taylor series is what keeps parity)", async () => {
    // The defaults: the milder of the two cases, so this fails on the swell's sine alone.
    const { query, limits } = CASES[0];
    const page = await openWithNativeSin(harness, query);
    const worst = await worstDisagreement(page, parityCases());
    console.log(
      `[oceano] CPU–GPU parity with native sin (${query}): max |Δheight| = ${worst.height.toExponential(2)} m, max |Δnormal| = ${worst.normal.toExponential(2)}`,
    );
    expect(worst.height).toBeGreaterThan(limits.height);
    expect(worst.normal).toBeGreaterThan(limits.normal);
    await page.close();
  });
});
