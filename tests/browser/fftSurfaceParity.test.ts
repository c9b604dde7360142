import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { seededRandom } from '../../src/sim/noise/integerHash';

/**
 * waves=fft: the drawn mesh against the CPU twin. The GPU probe runs the real chunk
 * (shaders/waves/fft.glsl reading the GPU FFT's float32 textures) at grid points p and
 * returns where the vertex goes, p + D(p); the twin (FftWaveModel, float64 fields, fixed-point
 * inversion) is then asked for the height above that very world point with sampleSurface, as
 * the boat asks. Far from the origin and late in time (t = 10⁶ s), where float32 would drift
 * if the phase or tile offsets were not reduced first.
 */
const PARITY_SEED = 20261121;
const TIMES = [0, 37.25, 4321.5, 100_000.125, 1_000_000];
const POINTS_PER_TIME = 96;
const EXTENT = 3000;
/**
 * The bound. Measured worst |Δheight|: 0.24 mm (fresh breeze), 0.76 mm (gale, λ = 1.2: the
 * float32 FFT of metre-high waves); worst |Δnormal| 1.5e-4; the negative control 3.5 cm.
 */
const HEIGHT_TOLERANCE = 1e-3;

const harness = useHarness();

/** Fresh breeze (the defaults) and a gale with full choppiness: the hardest case for the inversion. */
const QUERIES = ['waves=fft&seed=3&t=0&foam=false', 'waves=fft&seed=7&t=0&windSpeed=20&choppiness=1.2&foam=false'];

type Cases = { t: number; points: [number, number][] }[];

async function compare(query: string, cases: Cases, timeShift: number) {
  const { page } = await openOcean(harness, query);
  const result = await page.evaluate(
    async (cases, timeShift) => {
      const o = window.oceano;
      o.pause();
      let height = 0;
      let normal = 0;
      let at = { x: 0, z: 0, t: 0 };
      for (const { t, points } of cases) {
        const gpu = await o.probeGpu(points, t);
        o.setTime(t + timeShift);
        points.forEach(([x, z], i) => {
          const d = gpu[i];
          const world: [number, number] = [x + d.displacement[0], z + d.displacement[2]];
          const cpu = o.sampleSurface(world[0], world[1]);
          const dh = Math.abs(cpu.height - d.displacement[1]);
          if (dh > height) at = { x, z, t };
          height = Math.max(height, dh);
          for (let c = 0; c < 3; c++) normal = Math.max(normal, Math.abs(cpu.normal[c] - d.normal[c]));
        });
      }
      return { height, normal, at };
    },
    cases,
    timeShift,
  );
  await page.close();
  return result;
}

function randomCases(): Cases {
  const random = seededRandom(PARITY_SEED);
  // Grid points as float32, as every ocean vertex's are, so both sides evaluate the same (x, z).
  return TIMES.map((t) => ({
    t,
    points: Array.from(
      { length: POINTS_PER_TIME },
      () => [Math.fround((random() * 2 - 1) * EXTENT), Math.fround((random() * 2 - 1) * EXTENT)] as [number, number],
    ),
  }));
}

describe('waves=fft: CPU twin vs drawn mesh', () => {
  // TIMES.length × POINTS_PER_TIME points, |x| and |z| up to EXTENT.
  it.each(QUERIES)(`agrees within 1 mm on seeded random points out to ${EXTENT} m and up to t = 1e6 s: %s`, async (query) => {
    const worst = await compare(query, randomCases(), 0);
    console.log(
      `[oceano] FFT CPU–GPU parity (${query}): max |Δheight| = ${worst.height.toExponential(2)} m at (${worst.at.x}, ${worst.at.z}, t=${worst.at.t}), max |Δnormal| = ${worst.normal.toExponential(2)}`,
    );
    expect(worst.height).toBeLessThan(HEIGHT_TOLERANCE);
    expect(worst.normal).toBeLessThan(1e-3);
  });

  it('negative control: the twin 20 ms late (one frame) is caught', async () => {
    const worst = await compare(QUERIES[0], randomCases().slice(0, 2), 0.02);
    console.log(`[oceano] FFT parity negative control (CPU 20 ms late): max |Δheight| = ${worst.height.toExponential(2)} m`);
    expect(worst.height).toBeGreaterThan(HEIGHT_TOLERANCE);
  });
});
