import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { seededRandom } from '../../src/sim/noise/integerHash';

/**
 * The coast's CPU twin (src/sim/coast/coastSurface.ts: the swell's field read as the GPU reads
 * it, the wind sea calmed by depth) against shaders/coast.glsl read back from the GPU, on
 * seeded points over the shelf, the shore and beyond the field's grid, early and late.
 * The swell is the sum of four components limited to γ h (shaders/coast.glsl, coastSwellAt on
 * the CPU). The limits stand just above what SwiftShader measures here (float32 phases of up
 * to a few hundred radians, bilinear reads of float texels): max |Δheight| 1.70e-4 m and
 * 1.24e-4 m, max |Δnormal| 1.64e-5 and 1.03e-5, for the first two cases, 1.39e-4 m and 1.45e-5 for
 * the beach re-phased by a new seed; Gerstner's sea calmed at the beach 1.47e-4 m. Every component read 0.01 rad
 * late (the negative control) is 9.58e-3 m off, 32 times the height limit.
 */
const PARITY_SEED = 20261128;
const TIMES = [0, 37.25, 4321.5];
const POINTS_PER_TIME = 200;
const LIMITS = { height: 3e-4, normal: 3e-5 };

const harness = useHarness();

const CASES = [
  // The beach with the wind sea: shelf from x = −2600 m to the shore at 400 m, and land beyond.
  { query: 'preset=beach&t=0', x: [-3500, 700], z: [-2500, 2500] },
  // The island without the wind sea: the swell alone, wrapped round the island at (700, 0).
  { query: 'preset=island&windSea=0&t=0', x: [-800, 2200], z: [-1500, 1500] },
  // The beach re-phased by a new seed after it was built: the components' offsets change on both sides, nothing is rebuilt.
  { query: 'preset=beach&windSea=0&t=0', x: [-3500, 700], z: [-2500, 2500], seed: 5 },
  // Gerstner's trochoids as the wind sea over the shallows and the sand: their sideways motion calmed with
  // their height. The normal within Gerstner's own limit (wakeParity.test.ts): measured 3.3e-5.
  { query: 'preset=beach&waves=gerstner&t=0', x: [-600, 500], z: [-500, 500], normalLimit: 1e-3 },
];

type Case = { t: number; points: [number, number][] };

function parityCases(x: number[], z: number[]): Case[] {
  const random = seededRandom(PARITY_SEED);
  // On the float32 lattice, as every vertex is: both sides evaluate the very same (x, z).
  const pick = (range: number[]) => Math.fround(range[0] + random() * (range[1] - range[0]));
  return TIMES.map((t) => ({ t, points: Array.from({ length: POINTS_PER_TIME }, () => [pick(x), pick(z)] as [number, number]) }));
}

function worstDisagreement(page: Page, cases: Case[], seed?: number) {
  return page.evaluate(
    async (cases, seed) => {
      const o = window.oceano;
      o.pause();
      // With a new seed, how far the swell moved at a point of the shelf (0 if the seed changed nothing).
      let moved = 0;
      if (seed !== undefined) {
        o.setTime(cases[0].t);
        const before = o.sampleSurface(-1000, 0).height;
        await o.setParams({ seed });
        moved = Math.abs(o.sampleSurface(-1000, 0).height - before);
      }
      let height = 0;
      let normal = 0;
      let swell = 0;
      for (const { t, points } of cases) {
        o.setTime(t);
        const gpu = await o.probeGpu(points, t);
        points.forEach(([x, z], i) => {
          // The GPU answers at the grid point; the twin at the world point where it lands (the same with no sideways motion).
          const d = gpu[i].displacement;
          const cpu = o.sampleSurface(x + d[0], z + d[2]);
          height = Math.max(height, Math.abs(cpu.height - gpu[i].height));
          swell = Math.max(swell, Math.abs(cpu.height));
          for (let c = 0; c < 3; c++) normal = Math.max(normal, Math.abs(cpu.normal[c] - gpu[i].normal[c]));
        });
      }
      return { height, normal, swell, moved };
    },
    cases,
    seed,
  );
}

/** Makes the page's shaders read every component of the swell 0.01 rad late: a fault the limits must catch. */
async function withLateSwell(page: Page): Promise<void> {
  await page.evaluateOnNewDocument(() => {
    const original = WebGL2RenderingContext.prototype.shaderSource;
    WebGL2RenderingContext.prototype.shaderSource = function (shader: WebGLShader, source: string) {
      original.call(
        this,
        shader,
        source.replace('float theta = phaseAmplitude.x - advance[m];', 'float theta = phaseAmplitude.x - advance[m] - 0.01;'),
      );
    };
  });
}

describe("the coast's CPU twin vs its shader", () => {
  it.each(CASES)(
    'agrees within the limits on seeded points over shelf, shore and beyond: $query',
    async ({ query, x, z, seed, normalLimit }) => {
      const { page, consoleErrors } = await openOcean(harness, query);
      const worst = await worstDisagreement(page, parityCases(x, z), seed);
      console.log(
        `[oceano] coast parity (${query}${seed !== undefined ? `, then seed ${seed}` : ''}): max |Δheight| = ${worst.height.toExponential(2)} m, max |Δnormal| = ${worst.normal.toExponential(2)}, largest |η| ${worst.swell.toFixed(2)} m`,
      );
      expect(consoleErrors).toEqual([]);
      // The sea moves: a twin that answered 0 everywhere would agree with a shader that drew nothing.
      expect(worst.swell).toBeGreaterThan(0.3);
      // A new seed must re-phase the swell, not leave it as it was (both sides agreeing on a stale sea).
      if (seed !== undefined) expect(worst.moved).toBeGreaterThan(0.01);
      expect(worst.height).toBeLessThan(LIMITS.height);
      expect(worst.normal).toBeLessThan(normalLimit ?? LIMITS.normal);
      await page.close();
    },
  );

  it('rejects a swell read 0.01 rad late on the GPU (negative control)', async () => {
    const { query, x, z } = CASES[1];
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
    await withLateSwell(page);
    await page.goto(`${harness.baseUrl}?${query}`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    const worst = await worstDisagreement(page, parityCases(x, z));
    console.log(`[oceano] coast parity with a late swell: max |Δheight| = ${worst.height.toExponential(2)} m`);
    expect(worst.height).toBeGreaterThan(LIMITS.height);
    await page.close();
  });
});
