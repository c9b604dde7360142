import { buildCoastField } from '../src/sim/coast/coastSwellField';
import { sampleCoastField } from '../src/sim/coast/coastFieldSampling';
import { ISLAND_CENTER, ISLAND_RADIUS } from '../src/sim/coast/bathymetry';
import { findLesson, lessonView } from '../src/app/lessons/lessonCatalog';
const p = lessonView(findLesson('coast-refraction')!).params;
console.log(p.swellHeight, p.swellPeriod, p.beachSlope, p.seed, p.swellDirection);
const s = { bathymetry: p.bathymetry, beachSlope: p.beachSlope, deepDepth: p.depth, swellHeight: p.swellHeight, swellPeriod: p.swellPeriod, swellDirection: p.swellDirection, seed: p.seed };
const t0 = performance.now();
const f = buildCoastField(s, 256)!;
console.log('build ms', performance.now() - t0);
for (const d of [50, 100, 200, 300, 400]) {
  const x = ISLAND_CENTER[0] + ISLAND_RADIUS + d;
  const A = f.components.map((_, m) => sampleCoastField(f, x, 0, m).amplitude);
  const hs = 4 * Math.sqrt(A.reduce((a, b) => a + b * b, 0) / 2);
  console.log(d, A.map(a=>a.toFixed(3)), 'Hs', hs.toFixed(3), 'depth', sampleCoastField(f, x, 0).depth);
}
