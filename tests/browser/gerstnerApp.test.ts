import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { seededRandom } from '../../src/sim/noise/integerHash';

/**
 * waves=gerstner in the running app: the GPU probe runs the ocean's own chunk
 * (shaders/waves/gerstner.glsl, through the same WaveBinding as every ocean material) at grid
 * points p; the displaced point q = p + Dₕ(p) it returns is handed to the page's
 * sampleSurface, which must undo the horizontal motion (Newton, invertGerstner) and find the
 * same height and normal. This holds the GLSL, the uniforms' upload, the CPU twin and its
 * inversion together, far out and late in time.
 */
const PARITY_SEED = 20261122;
const TIMES = [0, 37.25, 100_000.125, 987_654.3];
const POINTS_PER_TIME = 128;
const EXTENT = 3000;

const harness = useHarness();

/** The default sea, and the steepest the parameters allow (64 waves at Q = 1 in a 20 m/s wind). */
const QUERIES = ['waves=gerstner&t=0', 'waves=gerstner&t=0&gerstnerCount=64&gerstnerSteepness=1&windSpeed=20&seed=7'];

interface Worst {
  height: number;
  normal: number;
  /** Negative control 1: the CPU read above the grid point, without undoing Dₕ. */
  uninverted: number;
  /** Negative control 2: the GPU probed 5 ms late. */
  late: number;
}

describe('waves=gerstner: CPU twin vs the GPU chunk in the app', () => {
  // TIMES.length × POINTS_PER_TIME points, |x| and |z| up to EXTENT.
  it.each(QUERIES)(`agrees within 1e-4 m on seeded points out to ${EXTENT} m, t ≤ 1e6 s, and the controls fail: %s`, async (query) => {
    const random = seededRandom(PARITY_SEED);
    const cases = TIMES.map((t) => ({
      t,
      points: Array.from(
        { length: POINTS_PER_TIME },
        () => [Math.fround((random() * 2 - 1) * EXTENT), Math.fround((random() * 2 - 1) * EXTENT)] as [number, number],
      ),
    }));
    const { page, consoleErrors } = await openOcean(harness, query);
    const worst: Worst = await page.evaluate(async (cases) => {
      const o = window.oceano;
      o.pause();
      const w = { height: 0, normal: 0, uninverted: 0, late: 0 };
      for (const { t, points } of cases) {
        o.setTime(t);
        const gpu = await o.probeGpu(points, t);
        const late = await o.probeGpu(points, t + 0.005);
        points.forEach(([x, z], i) => {
          const d = gpu[i].displacement;
          const cpu = o.sampleSurface(x + d[0], z + d[2]);
          w.height = Math.max(w.height, Math.abs(cpu.height - d[1]));
          for (let c = 0; c < 3; c++) w.normal = Math.max(w.normal, Math.abs(cpu.normal[c] - gpu[i].normal[c]));
          w.uninverted = Math.max(w.uninverted, Math.abs(o.sampleSurface(x, z).height - d[1]));
          w.late = Math.max(w.late, Math.abs(cpu.height - late[i].displacement[1]));
        });
      }
      return w;
    }, cases);
    console.log(
      `[oceano] gerstner parity (${query}): |Δh| ${worst.height.toExponential(2)} m, |Δn| ${worst.normal.toExponential(2)}; ` +
        `controls: uninverted ${worst.uninverted.toExponential(2)} m, 5 ms late ${worst.late.toExponential(2)} m`,
    );
    expect(consoleErrors).toEqual([]);
    expect(worst.height).toBeLessThan(1e-4);
    expect(worst.normal).toBeLessThan(1e-3);
    // The controls: each planted fault must break the 1e-4 m budget by far.
    expect(worst.uninverted).toBeGreaterThan(1e-2);
    expect(worst.late).toBeGreaterThan(1e-3);
    await page.close();
  });

  it('the boat floats on it and the camera dips under it', async () => {
    const { page, consoleErrors } = await openOcean(harness, 'waves=gerstner&t=10&gerstnerSteepness=1');
    const result = await page.evaluate(() => {
      const o = window.oceano;
      const boat = o.boat().target;
      const surface = o.sampleSurface(boat.position[0], boat.position[2]);
      o.setCamera({ position: [3, surface.height - 4, 5], target: [3, surface.height - 4, -20] });
      o.renderFrame();
      const below = o.stats().submersion;
      return { boatY: boat.position[1], surface: surface.height, below };
    });
    expect(consoleErrors).toEqual([]);
    // The hull rides within its draught of the surface it samples.
    expect(Math.abs(result.boatY - result.surface)).toBeLessThan(1.0);
    expect(result.below).toBe('below');
    await page.close();
  });
});
