// What many floating bodies cost: Ocean.sampleSurfaces for 1,000 points on the FFT sea, the
// same function the Ocean delegates to (src/sim/waves/surfaceBatch.ts) with the FFT twin's
// fields already at the time asked: its default answer, from the frame's own fields. Run alone with
// `npx tsx scripts/bench/batchSampleCost.ts`; `npm run bench` prints it with its figures.
import { FftWaveModel } from '../../src/sim/waves/fft/fftWaveModel';
import { sampleSurfaces } from '../../src/sim/waves/surfaceBatch';
import { defaultParams } from '../../src/sim/params/params';
import { seededRandom } from '../../src/sim/noise/integerHash';
import { median } from '../../src/sim/physics/sampleStatistics';

export const BATCH_POINTS = 1000;
const RUNS = 200;

export interface BatchSampleCost {
  sea: string;
  /** Median and fastest ms for one batch of BATCH_POINTS points, over RUNS batches. */
  medianMs: number;
  fastestMs: number;
}

export function batchSampleCosts(): BatchSampleCost[] {
  const seas = [
    { sea: 'FFT, default sea', params: { ...defaultParams(), waves: 'fft' as const } },
    { sea: 'FFT, gale (U = 20 m/s, λ = 1.2)', params: { ...defaultParams(), waves: 'fft' as const, windSpeed: 20, choppiness: 1.2 } },
  ];
  return seas.map(({ sea, params }) => {
    const model = new FftWaveModel(params);
    const random = seededRandom(5);
    // Buoys spread over a 400 m square, as examples/buoys.html spreads its own.
    const points = Float32Array.from({ length: 2 * BATCH_POINTS }, () => (random() - 0.5) * 400);
    const out = new Float32Array(4 * BATCH_POINTS);
    const times: number[] = [];
    for (let run = 0; run < RUNS + 20; run++) {
      const time = 10;
      const start = performance.now();
      sampleSurfaces(model, points, time, out);
      if (run >= 20) times.push(performance.now() - start);
    }
    if (!out.every(Number.isFinite)) throw new Error('sampleSurfaces answered a non-finite number.');
    return { sea, medianMs: median(times), fastestMs: Math.min(...times) };
  });
}

if (import.meta.url === `file://${process.argv[1]}`) {
  for (const c of batchSampleCosts())
    console.log(
      `sampleSurfaces, ${BATCH_POINTS} points, ${c.sea}: median ${c.medianMs.toFixed(3)} ms, fastest ${c.fastestMs.toFixed(3)} ms (budget 0.5 ms)`,
    );
}
