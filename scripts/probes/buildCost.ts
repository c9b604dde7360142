// One view's frame time in two builds, interleaved (a measurement: prints numbers, asserts
// nothing): `npx tsx scripts/probes/buildCost.ts VARIANT "query" [rounds] [WxH]` opens the query
// in dist/ and in dist/VARIANT/ (another commit's `vite build --outDir`), then each round times
// a block of 7 frames (renderFrame, median) on each page in turn, so a drifting load moves both
// alike. Prints the median of the rounds' ratios (this build over VARIANT) and their range.
import { median } from '../../src/sim/physics/sampleStatistics';
import { openOcean, startHarness } from '../../tests/browser/harness';

const [variant, query = 'waves=fft', roundsText = '8', size = '1280x720'] = process.argv.slice(2);
if (!variant) throw new Error('usage: scripts/probes/buildCost.ts VARIANT "query" [rounds] [WxH]');
const [width, height] = size.split('x').map(Number);
const block = `(() => {
  const ts = [];
  for (let i = 0; i < 7; i++) { const s = performance.now(); window.oceano.renderFrame(); ts.push(performance.now() - s); }
  ts.sort((a, b) => a - b);
  return ts[3];
})()`;
const harness = await startHarness();
try {
  const here = (await openOcean(harness, query, width, height)).page;
  const there = (await openOcean(harness, query, width, height, `${variant}/`)).page;
  for (const page of [here, there]) await page.evaluate(() => window.oceano.pause());
  const ratios: number[] = [];
  const times: [number[], number[]] = [[], []];
  for (let round = 0; round < Number(roundsText); round++) {
    for (const [i, page] of [here, there].entries()) {
      await page.bringToFront();
      times[i].push((await page.evaluate(block)) as number);
    }
    ratios.push(times[0][round] / times[1][round]);
  }
  console.log(
    `${query} at ${size}: this build ${median(times[0]).toFixed(1)} ms, ${variant} ${median(times[1]).toFixed(1)} ms; ratio ${median(ratios).toFixed(2)} (rounds ${Math.min(...ratios).toFixed(2)}–${Math.max(...ratios).toFixed(2)})`,
  );
} finally {
  await harness.close();
}
