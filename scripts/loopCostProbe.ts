/**
 * The app's main-thread figures with its own frame loop playing, as a live page runs
 * (a benchmark: prints numbers, asserts nothing): `oceano.stats().twinMs` (mean of the last 30
 * frames) and `cpuMs` (median of the last 30), read at the end of each block of 30 looped
 * frames, so every frame counts once. Then, as `npm run bench` takes cpuMs, the median of 30
 * paused frames drawn by renderFrame. Served with COOP + COEP as the bench is, so
 * performance.now() is fine-grained. Builds are interleaved block by block (A, B, A, B, …), so
 * a change of load hits both alike.
 *   npx vite build && npx vite build --outDir dist/NAME (the other variant)
 *   PROBE_BUILDS=NAME npx tsx scripts/loopCostProbe.ts [blocks] ["query;query"]
 */
import { loadavg } from 'node:os';
import type { Page } from 'puppeteer';
import { openOcean, startLongHarness } from './browserHarness';

const blocks = Number(process.argv[2] ?? 4);
const queries = (process.argv[3] ?? 't=10&waves=fft;t=10').split(';');
// PROBE_ROOT=0 leaves out dist/ itself.
const builds = [...(process.env.PROBE_ROOT === '0' ? [] : ['']), ...(process.env.PROBE_BUILDS ?? '').split(',').filter(Boolean).map((b) => `${b}/`)];
const BLOCK = 30;
// PROBE_SIZE=640x360: a smaller canvas, for a loaded machine (the update step and the twin do not depend on it).
const [WIDTH, HEIGHT] = (process.env.PROBE_SIZE ?? '1280x720').split('x').map(Number);
const harness = await startLongHarness();

/** Plays the loop for one block of frames; then the stats of exactly those frames. */
const loopBlock = (page: Page) =>
  page.evaluate(`(async () => {
    const o = window.oceano;
    const first = o.activity().framesDrawn;
    o.play();
    await new Promise((resolve) => {
      const timer = setInterval(() => {
        if (o.activity().framesDrawn - first < ${BLOCK}) return;
        clearInterval(timer);
        resolve();
      }, 2);
    });
    const s = o.stats();
    o.pause();
    return { twinMs: s.twinMs, cpuMs: s.cpuMs, frames: o.activity().framesDrawn - first, isolated: window.crossOriginIsolated };
  })()`) as Promise<{ twinMs: number | null; cpuMs: number; frames: number; isolated: boolean }>;

/** The bench's way: 30 paused frames by renderFrame (after 10 untimed), median update step. */
const pausedCpu = (page: Page) =>
  page.evaluate(`(() => {
    const o = window.oceano;
    o.pause();
    for (let i = 0; i < ${BLOCK + 10}; i++) o.renderFrame();
    return o.stats().cpuMs;
  })()`) as Promise<number>;

const median = (v: number[]) => [...v].sort((a, b) => a - b)[v.length >> 1];
try {
  console.log(`load average at start: ${loadavg().map((l) => l.toFixed(2)).join(' ')}`);
  for (const query of queries) {
    const pages = await Promise.all(builds.map((build) => openOcean(harness, query, WIDTH, HEIGHT, build, 600_000).then((o) => o.page)));
    const twin: number[][] = builds.map(() => []);
    const cpu: number[][] = builds.map(() => []);
    const paused: number[][] = builds.map(() => []);
    for (let b = 0; b < blocks; b++) {
      for (let i = 0; i < builds.length; i++) {
        await pages[i].bringToFront();
        const r = await loopBlock(pages[i]);
        if (!r.isolated) throw new Error('Not cross-origin isolated: timers are coarse.');
        if (r.twinMs !== null) twin[i].push(r.twinMs);
        cpu[i].push(r.cpuMs);
        paused[i].push(await pausedCpu(pages[i]));
      }
    }
    builds.forEach((build, i) => {
      const twinText = twin[i].length ? `twinMs mean ${(twin[i].reduce((a, c) => a + c, 0) / twin[i].length).toFixed(3)} (blocks ${twin[i].map((v) => v.toFixed(3)).join(' ')})` : 'twinMs null';
      console.log(`${build || 'dist/'} ${query}: ${blocks}×${BLOCK} looped frames: ${twinText}; cpuMs looped median of block medians ${median(cpu[i]).toFixed(3)} (${cpu[i].map((v) => v.toFixed(3)).join(' ')}); paused (bench's way) ${median(paused[i]).toFixed(3)} (${paused[i].map((v) => v.toFixed(3)).join(' ')})`);
    });
    await Promise.all(pages.map((p) => p.close()));
  }
  console.log(`load average at end: ${loadavg().map((l) => l.toFixed(2)).join(' ')}`);
} finally {
  await harness.close();
}
