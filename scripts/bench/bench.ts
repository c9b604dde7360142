/**
 * `npm run bench`: what the ocean costs, measured the same way every time. Serves the
 * built dist/ on loopback, drives headless Chromium at 1280×720 and a device pixel ratio
 * of 1, prints one JSON object and writes the same figures to scripts/bench/results.md.
 * It prints figures and asserts nothing: machines are too noisy for timed thresholds.
 *
 * BENCH_GPU=1 insists on the GPU, BENCH_GPU=0 on SwiftShader; unset, the GPU is tried and
 * SwiftShader used when it turns out to be software. The renderer string says which ran.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { cpus, loadavg } from 'node:os';
import puppeteer, { type Browser } from 'puppeteer';
import { preview, type PreviewServer } from 'vite';
import { locateBrowser, NO_BROWSER_MESSAGE } from '../../tests/browser/findBrowser.mjs';
import { openOcean, type Harness } from '../../tests/browser/harness';
import { CROSS_ORIGIN_ISOLATION } from '../../vite.config';
import { scriptSizes, type ScriptSizes } from '../build/distScripts';
import { median, percentile } from '../../src/sim/physics/sampleStatistics';
import { backendArgs, isSoftwareRenderer, requestedBackend, type Backend } from './browserBackend';
import { loopTwinMs, passTimeSamples, pageEnvironment, timeFloorFrames, timeOceanFrames, timeThreejsExampleFrames } from './pageMeasures';
import { COMPARISONS, SCENARIOS, type BenchScenario } from './scenarios';
import { openThreejsOceanExample, serveThreejsOceanExample } from './threejsOceanServer';
import { formatFigure, markdownTable } from './resultsTable';
import { sideBySideRatios, type SideBySideRatio } from './sideBySide';
import { BATCH_POINTS, batchSampleCosts, type BatchSampleCost } from './batchSampleCost';
import type { FrameCounts } from '../../src/render/diagnostics/frameCounter';
import { countFrames, formatCounts, guardRatio, type Guard } from './frameCountRows';

const WIDTH = 1280;
const HEIGHT = 720;
// BENCH_FRAMES lowers the count on a machine so loaded that 40 frames of each row take too long.
const FRAMES = Number(process.env.BENCH_FRAMES ?? 40);
if (!Number.isInteger(FRAMES) || FRAMES < 5) throw new Error(`BENCH_FRAMES must be an integer ≥ 5, got "${process.env.BENCH_FRAMES}".`);
const WARMUP = 5;
// The side-by-side ratios (sideBySide.ts): rounds, each a block of frames per row.
const SIDE_BY_SIDE = { rounds: Number(process.env.BENCH_ROUNDS ?? 8), framesPerBlock: 5 };
const PASS_FRAMES = 5;
// BENCH_ONLY=name,name runs only the scenarios whose names contain one of those words (e.g.
// BENCH_ONLY="default view,FFT view" for the FFT ratio) and writes scripts/bench/results-subset.md, so
// the full run's scripts/bench/results.md is not replaced by a partial one.
const ONLY = (process.env.BENCH_ONLY ?? '')
  .split(',')
  .map((word) => word.trim())
  .filter(Boolean);
// BENCH_COUNTS=only counts one frame of every Oceano row and times nothing: seconds, not minutes.
const COUNTS_ONLY = process.env.BENCH_COUNTS === 'only';
const RESULTS_FILE = ONLY.length ? 'scripts/bench/results-subset.md' : 'scripts/bench/results.md';
// The targets of issue 14, for the 2-core SwiftShader machine.
const TARGETS = { batchMs: 0.5, ratio: 20, cpuMs: 0.1, twinMs: 0.1, ttffMs: 800, pageKB: 200, componentExtraKB: 20 };
/** The mean of the figures, null if any is null (a model that does not measure it). */
function meanOrNull(values: (number | null)[]): number | null {
  if (values.some((v) => v === null)) return null;
  return (values as number[]).reduce((a, b) => a + b, 0) / values.length;
}

/** Looped frames for a scenario's twinMs: the stats' whole window (FrameStats keeps 30). */
const TWIN_FRAMES = 30;
/**
 * Windows of TWIN_FRAMES whose means are averaged: the mean over 120 frames. One frame of a few
 * ms (a collection, or the machine preempting the main thread inside a timed section) moves a
 * 30-frame mean by 0.1 ms, the whole budget; more frames weigh such frames as often as they
 * happen rather than as one in thirty.
 */
const TWIN_WINDOWS = 4;
// A page load on a machine shared by several jobs can take minutes; puppeteer's 30 s is too short.
const PAGE_TIMEOUT_MS = 300_000;

interface Timing {
  median: number;
  p95: number;
}

interface ScenarioResult {
  name: string;
  page: 'oceano' | 'threejs-ocean';
  query: string;
  /** Median time of each render pass over PASS_FRAMES profiled frames, ms. */
  passesMs?: Record<string, number>;
  frameMs: Timing;
  ratio: number;
  triangles: number;
  drawCalls: number;
  cpuMs: number;
  /** The wave twin's main-thread ms per frame, clock playing (scenarios with `twin`). */
  twinMs?: number | null;
  /** The mean of each window of TWIN_FRAMES looped frames (twinMs is their mean). */
  twinMsWindows?: (number | null)[];
  ttffMs: number | null;
  /** One frame's draw calls, passes, program switches and bytes uploaded (oceano.debug.frameCounts); null for three.js's example. */
  counts: FrameCounts | null;
}

const round = (value: number, decimals: number) => Number(value.toFixed(decimals));
/** Each pass's median time, ms, to 0.1 ms. */
const medianOfEach = (samples: Record<string, number[]>): Record<string, number> =>
  Object.fromEntries(Object.entries(samples).map(([name, values]) => [name, Math.round(median(values) * 10) / 10]));
const timing = (samples: number[]): Timing => ({ median: round(median(samples), 3), p95: round(percentile(samples, 95), 3) });

/**
 * The preview server is cross-origin isolated (vite.config.ts's CROSS_ORIGIN_ISOLATION, as
 * `npm start`), which also makes Chromium's performance.now() fine-grained (microseconds
 * instead of 0.1 ms), as a per-frame CPU time of a fraction of a millisecond needs.
 */
async function startServer(): Promise<{ server: PreviewServer; baseUrl: string }> {
  const server = await preview({ preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'error' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('The preview server has no TCP address.');
  return { server, baseUrl: `http://127.0.0.1:${address.port}/` };
}

/**
 * The browser's first WebGL2 context, made in a blank page: it starts Chromium's GPU
 * process (and SwiftShader in it), a one-time cost of a fresh headless browser that a
 * desktop browser, whose compositor already runs on the GPU, has paid before any page.
 * Timed and reported apart, so that ttffMs is the app's own start-up.
 */
async function startGpuProcess(browser: Browser): Promise<{ renderer: string | null; ms: number }> {
  const page = await browser.newPage();
  const result = await page.evaluate(() => {
    const start = performance.now();
    const gl = document.createElement('canvas').getContext('webgl2');
    const ms = performance.now() - start;
    if (!gl) return { renderer: null, ms };
    const debugInfo = gl.getExtension('WEBGL_debug_renderer_info');
    return { renderer: String(gl.getParameter(debugInfo ? debugInfo.UNMASKED_RENDERER_WEBGL : gl.RENDERER)), ms };
  });
  await page.close();
  return result;
}

/** Launches Chromium on the requested backend; in auto mode falls back to SwiftShader when the GPU path is software or absent. */
async function launchBrowser(): Promise<{ browser: Browser; backend: Backend; gpuStartupMs: number }> {
  const requested = requestedBackend(process.env.BENCH_GPU);
  const executablePath = await locateBrowser();
  if (!executablePath) throw new Error(NO_BROWSER_MESSAGE);
  // One page.evaluate times all of a row's frames: on a busy machine that outlasts puppeteer's 180 s protocol timeout.
  const launch = (backend: Backend) =>
    puppeteer.launch({ executablePath, args: backendArgs(backend), headless: true, protocolTimeout: 3_600_000 });
  if (requested !== 'swiftshader') {
    const browser = await launch('gpu');
    const { renderer, ms } = await startGpuProcess(browser);
    if (renderer !== null && !isSoftwareRenderer(renderer)) return { browser, backend: 'gpu', gpuStartupMs: ms };
    await browser.close();
    if (requested === 'gpu') {
      throw new Error(
        `BENCH_GPU=1 but Chromium's GPU path gave ${renderer === null ? 'no WebGL2' : `the software renderer "${renderer}"`}.`,
      );
    }
  }
  const browser = await launch('swiftshader');
  const { renderer, ms } = await startGpuProcess(browser);
  if (renderer === null) {
    await browser.close();
    throw new Error('Chromium with SwiftShader gave no WebGL2 context.');
  }
  return { browser, backend: 'swiftshader', gpuStartupMs: ms };
}

async function main(): Promise<void> {
  const started = performance.now();
  // Other work on the machine slows every figure; the load says how busy it was.
  const loadAverage = round(loadavg()[0], 1);
  const sizes = scriptSizes('dist');
  // Measured first, before the browser competes for the cores.
  const batchSamples = COUNTS_ONLY ? [] : batchSampleCosts();
  const { server, baseUrl } = await startServer();
  const example = await serveThreejsOceanExample(CROSS_ORIGIN_ISOLATION);
  const exampleBaseUrl = example.baseUrl;
  const { browser, backend, gpuStartupMs } = await launchBrowser();
  const harness: Harness = { browser, baseUrl, close: async () => undefined };
  try {
    const results: ScenarioResult[] = [];
    let renderer = '';
    let crossOriginIsolated = false;
    let floorTimes: number[] = [];
    const scenarios = ONLY.length ? SCENARIOS.filter((s) => ONLY.some((word) => s.name.includes(word))) : SCENARIOS;
    if (scenarios.length === 0)
      throw new Error(`BENCH_ONLY="${process.env.BENCH_ONLY}" matches no scenario in scripts/bench/scenarios.ts.`);
    if (COUNTS_ONLY) return await printCountsOnly(harness, scenarios);
    for (const scenario of scenarios) {
      if (scenario.page === 'threejs-ocean') {
        results.push(await timeThreejsExample(browser, exampleBaseUrl, scenario));
        continue;
      }
      const { page, consoleErrors } = await openOcean(harness, scenario.query, WIDTH, HEIGHT, '', PAGE_TIMEOUT_MS);
      await scenario.setup?.(page);
      const environment = await page.evaluate(pageEnvironment);
      const frames = await page.evaluate(
        timeOceanFrames,
        scenario.frames ?? FRAMES,
        scenario.frames ? 1 : WARMUP,
        scenario.stepSeconds ?? 0,
        Number(new URLSearchParams(scenario.query).get('t') ?? 0),
      );
      const counts = await countFrames(page, scenario.stepSeconds ?? 0);
      const passesMs = scenario.passes ? medianOfEach(await page.evaluate(passTimeSamples, PASS_FRAMES)) : undefined;
      const twinWindows: (number | null)[] = [];
      for (let w = 0; scenario.twin && w < TWIN_WINDOWS; w++) twinWindows.push(await page.evaluate(loopTwinMs, TWIN_FRAMES));
      const twinMs = scenario.twin ? meanOrNull(twinWindows) : undefined;
      if (frames.canvas[0] !== WIDTH || frames.canvas[1] !== HEIGHT) {
        throw new Error(`Scenario "${scenario.name}": the canvas is ${frames.canvas.join('×')}, not ${WIDTH}×${HEIGHT}.`);
      }
      if (floorTimes.length === 0) {
        // The floor is a property of the machine: measured once, in the first page, at the canvas's size.
        const floor = await page.evaluate(timeFloorFrames, WIDTH, HEIGHT, FRAMES, WARMUP);
        floorTimes = floor.frameTimes;
        renderer = environment.renderer;
        crossOriginIsolated = environment.crossOriginIsolated;
      }
      if (consoleErrors.length) throw new Error(`Scenario "${scenario.name}" logged errors: ${consoleErrors.join(' / ')}`);
      await page.close();
      results.push({
        name: scenario.name,
        page: 'oceano',
        query: scenario.query,
        frameMs: timing(frames.frameTimes),
        ratio: Number.NaN,
        triangles: frames.triangles,
        drawCalls: frames.drawCalls,
        cpuMs: round(frames.cpuMs, 4),
        ttffMs: frames.ttffMs === null ? null : round(frames.ttffMs, 1),
        counts,
        ...(passesMs ? { passesMs } : {}),
        ...(twinMs !== undefined
          ? {
              twinMs: twinMs === null ? null : round(twinMs, 4),
              twinMsWindows: twinWindows.map((ms) => (ms === null ? null : round(ms, 4))),
            }
          : {}),
      });
    }
    const floorMs = timing(floorTimes);
    for (const result of results) result.ratio = round(result.frameMs.median / floorMs.median, 2);
    const comparisons = COMPARISONS.map(([label, numerator, denominator, target]) => {
      const median = (name: string) =>
        name === 'floor' ? floorMs.median : (results.find((r) => r.name === name)?.frameMs.median ?? Number.NaN);
      return { label, ratio: round(median(numerator) / median(denominator), 2), target };
    });
    // A subset run (BENCH_ONLY) prints only the ratios whose two rows it ran.
    const comparisonsRun = comparisons.filter((c) => ONLY.length === 0 || Number.isFinite(c.ratio));
    const sideBySide = await sideBySideRatios(browser, harness, exampleBaseUrl, scenarios, {
      width: WIDTH,
      height: HEIGHT,
      ...SIDE_BY_SIDE,
      pageTimeoutMs: PAGE_TIMEOUT_MS,
    });
    const [headline] = results;
    const report = {
      // First, so that it is seen at every run: the SwiftShader guard, side by side.
      guard: guardRatio(sideBySide),
      renderer,
      backend,
      browser: await browser.version(),
      machine: `${cpus().length} cores, ${cpus()[0]?.model.trim() ?? 'unknown CPU'}`,
      loadAverage,
      viewport: { width: WIDTH, height: HEIGHT, devicePixelRatio: 1 },
      framesPerFigure: FRAMES,
      fineTimers: crossOriginIsolated,
      frameMs: headline.frameMs,
      floorMs,
      ratio: headline.ratio,
      triangles: headline.triangles,
      drawCalls: headline.drawCalls,
      cpuMs: headline.cpuMs,
      ttffMs: headline.ttffMs,
      comparisons: comparisonsRun,
      sideBySide,
      gpuStartupMs: round(gpuStartupMs, 1),
      jsKB: { pageKB: round(sizes.pageKB, 1), componentExtraKB: round(sizes.componentExtraKB, 1), allKB: round(sizes.allKB, 1) },
      batchSamples,
      scenarios: results,
      loadAverageAtEnd: round(loadavg()[0], 1),
      benchSeconds: round((performance.now() - started) / 1000, 1),
    };
    console.error(`[bench] ${formatGuard(report.guard).replaceAll('**', '')}`);
    console.log(JSON.stringify(report, null, 2));
    mkdirSync(dirname(RESULTS_FILE), { recursive: true });
    writeFileSync(RESULTS_FILE, resultsMarkdown(report, new Date()));
    console.error(`[bench] figures written to ${RESULTS_FILE}`);
  } finally {
    await browser.close();
    await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
    await example.close();
  }
}

/** BENCH_COUNTS=only: each Oceano row's frame counted after a few frames drawn as the bench draws them; printed as JSON and a table. */
async function printCountsOnly(harness: Harness, scenarios: readonly BenchScenario[]): Promise<void> {
  const rows: { name: string; query: string; counts: FrameCounts }[] = [];
  for (const scenario of scenarios) {
    if (scenario.page === 'threejs-ocean') continue;
    const { page } = await openOcean(harness, scenario.query, WIDTH, HEIGHT, '', PAGE_TIMEOUT_MS);
    await scenario.setup?.(page);
    const startTime = Number(new URLSearchParams(scenario.query).get('t') ?? 0);
    await page.evaluate(timeOceanFrames, 1, 2, scenario.stepSeconds ?? 0, startTime);
    rows.push({ name: scenario.name, query: scenario.query, counts: await countFrames(page, scenario.stepSeconds ?? 0) });
    await page.close();
  }
  console.log(JSON.stringify({ viewport: { width: WIDTH, height: HEIGHT }, rows }, null, 2));
  console.error(
    markdownTable(
      ['scenario', 'draw calls', 'passes', 'program switches', 'bytes uploaded'],
      rows.map((r) => [r.name, ...formatCounts(r.counts)]),
    ),
  );
}

/** One row from the copy of three.js's ocean example, timed like Oceano's frames. */
async function timeThreejsExample(browser: Browser, baseUrl: string, scenario: BenchScenario): Promise<ScenarioResult> {
  const { page, errors } = await openThreejsOceanExample(browser, baseUrl, scenario.query, WIDTH, HEIGHT, PAGE_TIMEOUT_MS);
  const frames = await page.evaluate(timeThreejsExampleFrames, FRAMES, WARMUP);
  await page.close();
  if (errors.length) throw new Error(`Scenario "${scenario.name}" logged errors: ${errors.join(' / ')}`);
  if (frames.canvas[0] !== WIDTH || frames.canvas[1] !== HEIGHT) {
    throw new Error(`Scenario "${scenario.name}": the canvas is ${frames.canvas.join('×')}, not ${WIDTH}×${HEIGHT}.`);
  }
  return {
    name: scenario.name,
    page: 'threejs-ocean',
    query: scenario.query,
    frameMs: timing(frames.frameTimes),
    ratio: Number.NaN,
    triangles: frames.triangles,
    drawCalls: frames.drawCalls,
    cpuMs: Number.NaN,
    ttffMs: null,
    counts: null,
  };
}

interface Report {
  guard: Guard | null;
  renderer: string;
  backend: Backend;
  browser: string;
  machine: string;
  loadAverage: number;
  loadAverageAtEnd: number;
  framesPerFigure: number;
  fineTimers: boolean;
  floorMs: Timing;
  ratio: number;
  cpuMs: number;
  ttffMs: number | null;
  gpuStartupMs: number;
  jsKB: Omit<ScriptSizes, 'pageFiles'>;
  comparisons: { label: string; ratio: number; target: number | null }[];
  sideBySide: SideBySideRatio[];
  batchSamples: BatchSampleCost[];
  scenarios: ScenarioResult[];
}

/** The guard's line: its ratio, the target beside it, and whether it holds. */
function formatGuard(guard: Guard | null): string {
  if (!guard) return '**Guard** (default view ÷ three.js example, no bloom): not run in this subset.';
  const verdict = guard.ratio <= guard.target ? 'within' : '**over**';
  return `**Guard**, ${guard.label}: **${formatFigure(guard.ratio, 2)}** (rounds ${formatFigure(guard.min, 2)}–${formatFigure(guard.max, 2)}), target ≤ ${guard.target}: ${verdict}.`;
}

function resultsMarkdown(report: Report, when: Date): string {
  const rows = report.scenarios.map((s) => [
    s.name,
    s.page === 'threejs-ocean' ? `three.js example${s.query ? ` \`${s.query}\`` : ''}` : `\`${s.query}\``,
    formatFigure(s.frameMs.median, 1),
    formatFigure(s.frameMs.p95, 1),
    formatFigure(s.ratio, 1),
    String(s.triangles),
    String(s.drawCalls),
    formatFigure(s.cpuMs, 3),
    formatFigure(s.ttffMs, 0),
  ]);
  const targets = [
    ...report.comparisons.map((c) => [c.label, formatFigure(c.ratio, 2), c.target === null ? '—' : `≤ ${c.target}`]),
    ['cpuMs', formatFigure(report.cpuMs, 3), `≤ ${TARGETS.cpuMs}`],
    ...report.scenarios
      .filter((s) => s.twinMs !== undefined)
      .map((s) => [
        `twinMs: the wave twin's main thread per frame (${s.name}; mean of ${TWIN_WINDOWS}×${TWIN_FRAMES} looped frames, windows ${(s.twinMsWindows ?? []).map((ms) => formatFigure(ms ?? Number.NaN, 3)).join(', ')})`,
        formatFigure(s.twinMs ?? Number.NaN, 3),
        `≤ ${TARGETS.twinMs}`,
      ]),
    ...report.batchSamples.map((b) => [
      `Ocean.sampleSurfaces, ${BATCH_POINTS} points (${b.sea}; median of node's runs, fastest ${formatFigure(b.fastestMs, 3)} ms)`,
      formatFigure(b.medianMs, 3),
      `≤ ${TARGETS.batchMs}`,
    ]),
    ['ttffMs', formatFigure(report.ttffMs, 0), `≤ ${TARGETS.ttffMs}`],
    ['page JavaScript before the first frame (KB gzipped)', formatFigure(report.jsKB.pageKB, 1), `≤ ${TARGETS.pageKB}`],
    ["oceano.js beyond the page's code (KB gzipped)", formatFigure(report.jsKB.componentExtraKB, 1), `≤ ${TARGETS.componentExtraKB}`],
  ];
  return [
    '# Oceano benchmark results',
    '',
    formatGuard(report.guard),
    '',
    `Written by \`npm run bench\` on ${when.toISOString().slice(0, 16).replace('T', ' ')} UTC.`,
    '',
    `- Machine: ${report.machine}; load average ${report.loadAverage} when the bench started and ${report.loadAverageAtEnd} when it ended (anything above the core count slows every figure)`,
    '- three.js ocean example: a copy of examples/webgl_shaders_ocean.html built with the installed `three` (scripts/bench/threejsOcean, which says what differs: a generated normal map, fixed time), timed the same way in the same browser',
    `- Renderer: ${report.renderer} (${report.backend === 'gpu' ? 'GPU' : 'SwiftShader, software'})`,
    `- Browser: ${report.browser}, headless, 1280×720, device pixel ratio 1`,
    `- Each frame figure: ${report.framesPerFigure} frames after untimed warm-up, each ended by a one-pixel readPixels (GPU sync); timers ${report.fineTimers ? 'fine-grained (cross-origin isolated)' : 'coarse (0.1 ms)'}`,
    `- Floor (clear + full-screen quad, trivial shader, same size): median ${formatFigure(report.floorMs.median, 2)} ms, p95 ${formatFigure(report.floorMs.p95, 2)} ms`,
    `- JavaScript, gzipped: the page loads ${formatFigure(report.jsKB.pageKB, 1)} KB before its first frame; oceano.js adds ${formatFigure(report.jsKB.componentExtraKB, 1)} KB to the code it shares with the page; all of dist/ (lazy chunks included) is ${formatFigure(report.jsKB.allKB, 1)} KB`,
    `- ttffMs is the app's first load in a browser whose GPU process already runs; starting that process (the fresh headless browser's first WebGL context, timed in a blank page) took ${formatFigure(report.gpuStartupMs, 0)} ms and is not in it`,
    '',
    markdownTable(
      ['scenario', 'query', 'frame median (ms)', 'frame p95 (ms)', 'ratio to floor', 'triangles', 'draw calls', 'cpuMs', 'ttffMs'],
      rows,
    ),
    '',
    'What one frame asks of the GPU, counted from its WebGL calls (`oceano.debug.frameCounts`; the same on every machine):',
    '',
    markdownTable(
      ['scenario', 'draw calls', 'passes', 'program switches', 'bytes uploaded'],
      report.scenarios.filter((s) => s.counts).map((s) => [s.name, ...formatCounts(s.counts as FrameCounts)]),
    ),
    ...report.scenarios
      .filter((s) => s.passesMs)
      .flatMap((s) => [
        '',
        `Per-pass time, ${s.name} (median of ${PASS_FRAMES} frames, GPU waited for after each pass):`,
        '',
        markdownTable(
          ['pass', 'ms'],
          Object.entries(s.passesMs ?? {}).map(([name, ms]) => [name, formatFigure(ms, 1)]),
        ),
      ]),
    '',
    `Headline (${report.scenarios[0].name}) and the ratios between rows against the targets of issues 14 and 12 (FFT view / default ≤ 1.3), set for the 2-core SwiftShader machine:`,
    '',
    markdownTable(['figure', 'measured', 'target'], targets),
    '',
    `The same ratios measured side by side: every row's page open at once, ${SIDE_BY_SIDE.rounds} rounds, each timing a block of ${SIDE_BY_SIDE.framesPerBlock} frames on every page in turn; a round's ratio is of its two blocks' medians, the figure the median over the rounds (a load that drifts between minutes moves both rows alike):`,
    '',
    markdownTable(
      ['figure', 'median of the rounds', 'lowest round', 'highest round', 'target'],
      report.sideBySide.map((c) => [
        c.label,
        formatFigure(c.ratio, 2),
        formatFigure(c.min, 2),
        formatFigure(c.max, 2),
        c.target === null ? '—' : `≤ ${c.target}`,
      ]),
    ),
    '',
  ].join('\n');
}

await main();
