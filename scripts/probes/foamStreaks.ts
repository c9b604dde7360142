// How far the foam left behind is drawn out along the wind, seen from above (windDirection=90,
// so the wind runs along the picture's x): the streak anisotropy of tests/browser/light/windrowsPicture.test.ts
// at each instant and their mean. Prints figures, asserts nothing.
// Usage: npx vite build && npx tsx scripts/probes/foamStreaks.ts [altitude] [wind] ["&more=query"]
import { openOcean, startHarness } from '../../tests/browser/harness';
import { foamOwnLight } from '../../tests/browser/light/foamLight';
import { streakAnisotropy } from '../../tests/browser/light/streakMeasure';

const [altitude = '150', wind = '20', extra = ''] = process.argv.slice(2);
const W = 640;
const H = 360;
const TIMES = [20, 50, 80];
const BOX = 4;
const query = `waves=fft&windSpeed=${wind}&windDirection=90&sunElevation=30&cam=0,${altitude},0,0,0,-0.01${extra}`;

const harness = await startHarness();
try {
  const { page } = await openOcean(harness, query, W, H);
  const each: number[] = [];
  for (const t of TIMES) {
    each.push(streakAnisotropy(await foamOwnLight(page, t), W, H, BOX));
  }
  const mean = each.reduce((a, b) => a + b, 0) / each.length;
  console.log(JSON.stringify({ query, anisotropy: Number(mean.toFixed(3)), instants: each.map((a) => Number(a.toFixed(3))) }));
} finally {
  await harness.close();
}
