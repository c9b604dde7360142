// The default view against three.js's ocean example without bloom, side by side and nothing
// else (the bench's first guard, in a few minutes instead of the whole bench's hour): the pages open
// in one browser, rounds interleaved as `npm run bench` does (scripts/bench/sideBySide.ts), each
// block of frames timed by the wall clock and by the CPU time of Chromium's GPU process (where
// SwiftShader draws, on every core it is given; a load that slows the wall clock disturbs it less).
// With VARIANT (another commit's `vite build --outDir dist/VARIANT`), its default view joins the
// rounds, for this build against it as well. Prints medians of the rounds' ratios, their range and
// each round. A measure, no assertion.
// Usage: npx vite build && npx tsx scripts/probes/exampleRatio.ts [rounds] ["query"] [frames per block] [VARIANT]
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import type { Page } from 'puppeteer';
import { median } from '../../src/sim/physics/sampleStatistics';
import { openOcean, startHarness } from '../../tests/browser/harness';
import { CROSS_ORIGIN_ISOLATION } from '../../vite.config';
import { timeOceanFrames, timeThreejsExampleFrames } from '../bench/pageMeasures';
import { openThreejsOceanExample, serveThreejsOceanExample } from '../bench/threejsOceanServer';

const [roundsText = '6', query = 't=10', blockText = '6', variant = ''] = process.argv.slice(2);
const [width, height, framesPerBlock, pageTimeoutMs] = [1280, 720, Number(blockText), 600_000];
const example = await serveThreejsOceanExample(CROSS_ORIGIN_ISOLATION);
const harness = await startHarness();
// The GPU process starts with the first WebGL context, so it is looked for once a page has drawn;
// the browser's path may be a wrapper script, so it is any descendant of the launched process.
const parentOf = (pid: string) => readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ')[1];
const descends = (pid: string, ancestor: string): boolean =>
  pid !== '0' && pid !== '1' && (pid === ancestor || descends(parentOf(pid), ancestor));
let gpuPid = '';
const gpuCpuMs = () => {
  const browserPid = String(harness.browser.process()?.pid);
  gpuPid ||=
    execFileSync('pgrep', ['-f', 'type=gpu-process'])
      .toString()
      .trim()
      .split('\n')
      .find((pid) => descends(pid, browserPid)) ?? '';
  const fields = readFileSync(`/proc/${gpuPid}/stat`, 'utf8').split(') ')[1].split(' ');
  return ((Number(fields[11]) + Number(fields[12])) * 1000) / 100;
};
try {
  const startTime = Number(new URLSearchParams(query).get('t') ?? 0);
  const rows: { name: string; page: Page; frames: () => Promise<number[]> }[] = [];
  const addOcean = async (name: string, prefix: string) => {
    const { page } = await openOcean(harness, query, width, height, prefix, pageTimeoutMs);
    rows.push({ name, page, frames: async () => (await page.evaluate(timeOceanFrames, framesPerBlock, 1, 0, startTime)).frameTimes });
  };
  await addOcean(query, '');
  const three = (await openThreejsOceanExample(harness.browser, example.baseUrl, 'bloom=0', width, height, pageTimeoutMs)).page;
  rows.push({
    name: 'three.js example (no bloom)',
    page: three,
    frames: async () => (await three.evaluate(timeThreejsExampleFrames, framesPerBlock, 1)).frameTimes,
  });
  if (variant) await addOcean(`${query} at ${variant}`, `${variant}/`);
  const wall: number[][] = rows.map(() => []);
  const cpu: number[][] = rows.map(() => []);
  for (let round = 0; round < Number(roundsText); round++) {
    for (const [i, row] of rows.entries()) {
      await row.page.bringToFront();
      const before = gpuCpuMs();
      wall[i].push(median(await row.frames()));
      cpu[i].push((gpuCpuMs() - before) / (framesPerBlock + 1));
    }
  }
  const f = (x: number) => x.toFixed(2);
  const pairs: [number, number, string][] = [[0, 1, ' (guard ≤ 0.6)']];
  if (variant) pairs.push([2, 1, ''], [0, 2, '']);
  for (const [name, times] of [
    ['wall', wall],
    ['GPU-process CPU', cpu],
  ] as const) {
    for (const [a, b, note] of pairs) {
      const ratios = times[a].map((x, r) => x / times[b][r]);
      console.log(
        `${name}: ${rows[a].name} ${median(times[a]).toFixed(1)} ms / ${rows[b].name} ${median(times[b]).toFixed(1)} ms at ${width}×${height} = ` +
          `${f(median(ratios))} (rounds ${f(Math.min(...ratios))}–${f(Math.max(...ratios))}: ${ratios.map(f).join(', ')})${note}`,
      );
    }
  }
} finally {
  await harness.close();
  await example.close();
}
