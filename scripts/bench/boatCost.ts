// CPU cost of the boat's per-frame update (five surface samples, three damped springs):
// `npx tsx scripts/bench/boatCost.ts`. Prints figures; times nothing it asserts.
import { defaultParams } from '../../src/sim/params/params';
import { SeedWaveModel } from '../../src/sim/waves/seed/seedWaveModel';
import { median } from '../../src/sim/physics/sampleStatistics';
import { BoatMotion } from '../../src/sim/boat/boatMotion';

const FRAMES = 20_000;
const RUNS = 7;
const params = defaultParams();
const waves = new SeedWaveModel(params);
const hull = { length: 8, beam: 2.6 };
const perRun: number[] = [];
for (let run = 0; run < RUNS; run++) {
  const motion = new BoatMotion();
  const start = performance.now();
  for (let frame = 0; frame < FRAMES; frame++) {
    const time = 10 + frame / 60;
    motion.update(time, { heading: 1, speed: 3, response: params.boatResponse }, hull, (x, z) => waves.height(x, z, time));
  }
  perRun.push(((performance.now() - start) / FRAMES) * 1000);
}
console.log(
  `boat update: median ${median(perRun).toFixed(2)} µs per frame over ${RUNS} runs of ${FRAMES} frames (min ${Math.min(...perRun).toFixed(2)}, max ${Math.max(...perRun).toFixed(2)})`,
);
