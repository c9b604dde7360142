// The main thread's per-frame cost of the FFT sea's CPU twin while the clock plays:
// `npx tsx scripts/bench/fftTwinCost.ts`. The FFTs run in the Worker (here: fields computed
// ahead, outside the timing, and handed over as the Worker's reply would be); what is timed
// is what the main thread does each frame: receive the reply (structuredClone with the arrays
// transferred, as postMessage does: an upper bound, it also serialises, which the Worker does),
// adopt it, ask for the next time, and the ten surface heights a frame asks for (five under the
// boat, the eye, four near-plane points). The app measures the same work live as
// oceano.stats().twinMs (the bench's FFT row).
import { FftOcean } from '../../src/sim/waves/fft/fftOcean';
import { FftWaveModel, type FieldSource } from '../../src/sim/waves/fft/fftWaveModel';
import { defaultParams } from '../../src/sim/params/params';

const FRAMES = 240;
for (const windSpeed of [10, 20]) {
  const params = { ...defaultParams(), waves: 'fft' as const, windSpeed };
  const model = new FftWaveModel(params);
  const source: FieldSource = { request: () => {}, dispose: () => {} };
  model.attachSource(source);
  const worker = new FftOcean(model.sea);
  const replies = Array.from({ length: FRAMES }, (_, f) => {
    worker.setTime(10 + f / 60);
    return worker.fields.map((c) => ({ displacement: c.displacement.slice(), derivatives: c.derivatives.slice() }));
  });
  model.height(0, 0, 10); // the first frame computes at once (a jump)
  const costs: number[] = [];
  const receipts: number[] = [];
  for (let f = 1; f < FRAMES; f++) {
    const t = 10 + f / 60;
    const start = performance.now();
    const fields = replies[f - 1];
    const message = structuredClone(
      { time: t - 1 / 60, fields },
      { transfer: fields.flatMap((c) => [c.displacement.buffer, c.derivatives.buffer]) },
    );
    model.receive(model.sea, message.time, message.fields);
    receipts.push(performance.now() - start);
    model.prefetch(t);
    let sum = 0;
    for (let k = 0; k < 10; k++) sum += model.height(3 * k - 12, -5 + k, t);
    costs.push(performance.now() - start);
    if (!Number.isFinite(sum)) throw new Error('not finite');
  }
  costs.sort((a, b) => a - b);
  receipts.sort((a, b) => a - b);
  console.log(
    `FFT twin, U=${windSpeed} m/s: main thread per frame median ${costs[costs.length >> 1].toFixed(4)} ms, 90th percentile ${costs[Math.floor(costs.length * 0.9)].toFixed(4)} ms (10 heights, 12 fixed-point steps each; of which receiving the fields: median ${receipts[receipts.length >> 1].toFixed(4)} ms)`,
  );
  const t0 = performance.now();
  worker.setTime(123.4);
  console.log(
    `  Worker's FFTs for one time (3 cascades × 4 inverse FFTs, ${model.sea.fftSize}², float64): ${(performance.now() - t0).toFixed(1)} ms`,
  );
}
