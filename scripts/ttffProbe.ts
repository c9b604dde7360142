import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { BROWSER_ARGS, startHarness } from './browserHarness';
import { cpuByKind } from './procCpu';

/**
 * Where the time to first frame goes (issue 14's ttffMs): loads the app in a fresh headless
 * Chromium whose GPU process already runs (a blank page's WebGL2 context first, as the bench
 * does), so shader programs compile cold as on a first visit, and prints the app's
 * performance marks (oceano:*, from navigation start) and the scripts' fetch end, median of
 * N loads. `npx vite build && npx tsx scripts/ttffProbe.ts [loads] ["query|query"]`; PROBE_BUILDS=name
 * also loads dist/name (built with `vite build --outDir dist/name`), alternating, so two
 * builds are compared in one run on a busy machine.
 *
 * PROBE_CPU=1 also prints, at each mark, the CPU time the GPU process (where SwiftShader
 * draws) and the renderer process have spent since navigation started (`gpu:mark`,
 * `renderer:mark`, ms, 10 ms resolution): the cost of each start-up step whatever else the
 * machine runs. Each oceano:* mark then makes a synchronous request to this script, which
 * reads /proc while the page's main thread waits; that adds a few ms per mark to the wall
 * times, so compare wall times only between runs with the same setting.
 */
const loads = Number(process.argv[2] ?? 5);
/** Queries separated by '|' are loaded in turn, as builds are. */
const queries = (process.argv[3] ?? 't=10').split('|');
const builds = ['', ...(process.env.PROBE_BUILDS ? process.env.PROBE_BUILDS.split(',').map((b) => `${b}/`) : [])].flatMap((build) => queries.map((query) => `${build}?${query}`));
const withCpu = process.env.PROBE_CPU === '1';

/** The CPU readings of the load under way, by mark; filled by the mark server. */
let cpuAtMarks: Record<string, number> = {};
let cpuRoot = 0;
/** The browser's processes' CPU ms by kind when the load started (the same browser throughout a load). */
let cpuStart: Record<string, number> | undefined;
const cpuSince = (root: number, start: Record<string, number>) => {
  const now = cpuByKind(root);
  return { gpu: now.gpu - start.gpu, renderer: now.renderer - start.renderer };
};
const markServer = createServer((request, response) => {
  const name = decodeURIComponent((request.url ?? '').replace(/^\/\??/, ''));
  if (cpuStart) {
    const cpu = cpuSince(cpuRoot, cpuStart);
    cpuAtMarks[`gpu:${name}`] = cpu.gpu;
    cpuAtMarks[`renderer:${name}`] = cpu.renderer;
  }
  response.writeHead(204, { 'access-control-allow-origin': '*' });
  response.end();
});
if (withCpu) await new Promise<void>((resolve) => markServer.listen(0, '127.0.0.1', resolve));
const markUrl = withCpu ? `http://127.0.0.1:${(markServer.address() as AddressInfo).port}/` : '';

async function loadOnce(path: string): Promise<Record<string, number>> {
  const harness = await startHarness(BROWSER_ARGS);
  try {
    const warm = await harness.browser.newPage();
    await warm.evaluate(() => document.createElement('canvas').getContext('webgl2') !== null);
    await warm.close();
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 1280, height: 720, deviceScaleFactor: 1 });
    page.setDefaultTimeout(300_000);
    if (withCpu) {
      // The page's Content Security Policy allows connections to its own origin only.
      await page.setBypassCSP(true);
      // A string, not a function: tsx would wrap named helpers in a `__name` the page lacks.
      await page.evaluateOnNewDocument(`(() => {
        const mark = performance.mark.bind(performance);
        performance.mark = (name, options) => {
          const entry = mark(name, options);
          if (name.startsWith('oceano:')) {
            const request = new XMLHttpRequest();
            request.open('GET', ${JSON.stringify(markUrl)} + encodeURIComponent(name.slice(7)), false);
            request.send();
          }
          return entry;
        };
      })()`);
      cpuRoot = harness.browser.process()?.pid ?? 0;
      cpuAtMarks = {};
      cpuStart = cpuByKind(cpuRoot);
    }
    await page.goto(`${harness.baseUrl}${path}`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    const cpuReady = withCpu && cpuStart ? cpuSince(cpuRoot, cpuStart) : undefined;
    cpuStart = undefined;
    const out = await page.evaluate(() => {
      const out: Record<string, number> = {};
      for (const mark of performance.getEntriesByType('mark')) if (mark.name.startsWith('oceano:')) out[mark.name.slice(7)] = mark.startTime;
      const scripts = performance.getEntriesByType('resource').filter((r) => r.name.endsWith('.js'));
      out['scripts-fetched'] = Math.max(...scripts.map((r) => (r as PerformanceResourceTiming).responseEnd));
      out.ttffMs = window.oceano.stats().ttffMs ?? Number.NaN;
      out.readyMs = performance.now();
      out.programs = window.oceano.three.renderer.info.programs?.length ?? Number.NaN;
      return out;
    });
    if (cpuReady) Object.assign(out, cpuAtMarks, { 'gpu:ready': cpuReady.gpu, 'renderer:ready': cpuReady.renderer });
    return out;
  } finally {
    await harness.close();
  }
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const samples = new Map<string, Record<string, number>[]>(builds.map((b) => [b, []]));
for (let i = 0; i < loads; i++) for (const build of builds) samples.get(build)!.push(await loadOnce(build));
markServer.close();
for (const [build, runs] of samples) {
  console.log(`${build} (${runs.length} loads, median ms from navigation start):`);
  const print = (keys: string[]) => {
    // CPU readings in the order of their marks' wall times.
    const at = (key: string) => runs[0][key.replace(/^\w+:/, '').replace(/^ready$/, 'readyMs')];
    for (const key of keys.sort((a, b) => at(a) - at(b))) console.log(`  ${key.padEnd(24)} ${median(runs.map((r) => r[key] ?? Number.NaN)).toFixed(0).padStart(6)}   [${runs.map((r) => (r[key] ?? Number.NaN).toFixed(0)).join(' ')}]`);
  };
  const keys = Object.keys(runs[0]);
  print(keys.filter((k) => !k.includes(':')));
  for (const kind of ['gpu', 'renderer']) {
    const cpuKeys = keys.filter((k) => k.startsWith(`${kind}:`));
    if (cpuKeys.length === 0) continue;
    console.log(`  CPU ms of the ${kind} process since navigation, at each mark:`);
    print(cpuKeys);
  }
}
