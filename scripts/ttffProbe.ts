import { BROWSER_ARGS, startHarness } from './browserHarness';

/**
 * Where the time to first frame goes (issue 14's ttffMs): loads the app in a fresh headless
 * Chromium whose GPU process already runs (a blank page's WebGL2 context first, as the bench
 * does), so shader programs compile cold as on a first visit, and prints the app's
 * performance marks (oceano:*, from navigation start) and the scripts' fetch end, median of
 * N loads. `npx vite build && npx tsx scripts/ttffProbe.ts [loads] ["query|query"]`; PROBE_BUILDS=name
 * also loads dist/name (built with `vite build --outDir dist/name`), alternating, so two
 * builds are compared in one run on a busy machine.
 */
const loads = Number(process.argv[2] ?? 5);
/** Queries separated by '|' are loaded in turn, as builds are. */
const queries = (process.argv[3] ?? 't=10').split('|');
const builds = ['', ...(process.env.PROBE_BUILDS ? process.env.PROBE_BUILDS.split(',').map((b) => `${b}/`) : [])].flatMap((build) => queries.map((query) => `${build}?${query}`));

async function loadOnce(path: string): Promise<Record<string, number>> {
  const harness = await startHarness(BROWSER_ARGS);
  try {
    const warm = await harness.browser.newPage();
    await warm.evaluate(() => document.createElement('canvas').getContext('webgl2') !== null);
    await warm.close();
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 1280, height: 720, deviceScaleFactor: 1 });
    page.setDefaultTimeout(300_000);
    await page.goto(`${harness.baseUrl}${path}`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    return await page.evaluate(() => {
      const out: Record<string, number> = {};
      for (const mark of performance.getEntriesByType('mark')) if (mark.name.startsWith('oceano:')) out[mark.name.slice(7)] = mark.startTime;
      const scripts = performance.getEntriesByType('resource').filter((r) => r.name.endsWith('.js'));
      out['scripts-fetched'] = Math.max(...scripts.map((r) => (r as PerformanceResourceTiming).responseEnd));
      out.ttffMs = window.oceano.stats().ttffMs ?? Number.NaN;
      out.readyMs = performance.now();
      out.programs = window.oceano.three.renderer.info.programs?.length ?? Number.NaN;
      return out;
    });
  } finally {
    await harness.close();
  }
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const samples = new Map<string, Record<string, number>[]>(builds.map((b) => [b, []]));
for (let i = 0; i < loads; i++) for (const build of builds) samples.get(build)!.push(await loadOnce(build));
for (const [build, runs] of samples) {
  const keys = Object.keys(runs[0]).sort((a, b) => runs[0][a] - runs[0][b]);
  console.log(`${build} (${runs.length} loads, median ms from navigation start):`);
  for (const key of keys) console.log(`  ${key.padEnd(24)} ${median(runs.map((r) => r[key] ?? Number.NaN)).toFixed(0).padStart(6)}   [${runs.map((r) => (r[key] ?? Number.NaN).toFixed(0)).join(' ')}]`);
}
