/**
 * Where the FFT view's frame goes beyond its profiled passes (issue 12; a benchmark: prints
 * numbers, asserts nothing). With one page per build and view open at once, it goes round them
 * in blocks of frames, so a load that drifts from minute to minute moves every build and kind alike:
 *   paused:   renderFrame at an unchanged time (update + scene; the bench's default row),
 *   stepping: the clock moved 1/60 s before each renderFrame (the bench's FFT row),
 *   draw:     three's render of the scene alone, no update (what passTimings calls 'scene'),
 *   profile:  oceano.debug.passTimings() (each pass between two GPU syncs; the bench's per-pass
 *             table): its wall figure is the sum of the passes, each pass's median printed apart,
 * and per block the wall median and the GPU process's and the renderer process's CPU ms per
 * frame (SwiftShader draws in the GPU process; the page and its Workers are the renderer).
 * setTime asks the app's loop for a redraw, which it draws at the next animation frame, after
 * the block's evaluate: each block therefore waits for that frame and a GPU sync before the CPU
 * is read, and divides by the frames the app drew (oceano.activity().framesDrawn), not by the
 * frames it timed. (fftFrameProbe.ts divides by the timed frames, so its stepping rows carry
 * that extra frame: +1/frames of a frame.)
 * Ends with each row's median over the rounds. `PROBE_BUILDS=a,b` adds builds under dist/;
 * `PROBE_KINDS=draw,stepping` probes only those kinds.
 * Run after `vite build`: npx tsx scripts/fftGapProbe.ts [framesPerBlock] [rounds] [queries, ;-separated]
 */
import type { Page } from 'puppeteer';
import { openOcean, startHarness } from './browserHarness';
import { cpuByKind } from './procCpu';

const frames = Number(process.argv[2] ?? 4);
const rounds = Number(process.argv[3] ?? 5);
const queries = (process.argv[4] ?? 't=10;t=10&waves=fft').split(';');
const builds = ['', ...(process.env.PROBE_BUILDS ?? '').split(',').filter(Boolean).map((b) => `${b}/`)];
const ALL_KINDS = ['paused', 'stepping', 'draw', 'profile'];
/** PROBE_KINDS=draw,stepping probes only those kinds. */
const kinds = (process.env.PROBE_KINDS ?? ALL_KINDS.join(',')).split(',').filter((k) => ALL_KINDS.includes(k));
const passesByRow = new Map<string, Record<string, number[]>>();
const rows = new Map<string, { wall: number[]; gpu: number[]; renderer: number[] }>();

const harness = await startHarness();
const root = harness.browser.process()?.pid;
if (root === undefined) throw new Error('No browser process to measure.');
try {
  // Every build's page is opened first and the rounds go round all of them, so a load that
  // drifts between minutes moves every build alike (pages probed one after another differed
  // by 30 % on the same shader).
  const pages: { page: Page; name: string }[] = [];
  for (const build of builds) {
    for (const query of queries) pages.push({ page: (await openOcean(harness, query, 1280, 720, build, 600_000)).page, name: `${build || 'dist/'} ${query}` });
  }
  // The probed page in front: a background page gets no animation frames, and its loop stops.
  const block = async (page: Page, kind: string, count: number) => (await page.bringToFront(), page.evaluate(`(async () => {
    const o = window.oceano;
    o.pause();
    const gl = o.three.renderer.getContext();
    const pixel = new Uint8Array(4);
    const times = [];
    const passes = {};
    const drawn = o.activity().framesDrawn;
    for (let i = 0; i < ${count}; i++) {
      const start = performance.now();
      if ('${kind}' === 'draw') {
        o.three.renderer.render(o.three.scene, o.three.camera);
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      } else if ('${kind}' === 'profile') {
        let sum = 0;
        for (const p of o.debug.passTimings()) {
          (passes[p.name] ??= []).push(p.ms);
          sum += p.ms;
        }
        times.push(sum);
        continue;
      } else {
        if ('${kind}' === 'stepping') o.setTime(10 + (window.__gapFrame = (window.__gapFrame ?? 0) + 1) / 60);
        o.renderFrame();
      }
      times.push(performance.now() - start);
    }
    // The redraw setTime asked the loop for, then a GPU sync: its cost lands in this block.
    // (A page in the background gets no animation frames: at most 2 s.)
    await Promise.race([new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))), new Promise((r) => setTimeout(r, 2000))]);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    const frames = Math.max(${count}, o.activity().framesDrawn - drawn);
    times.sort((a, b) => a - b);
    return { median: times[Math.floor(times.length / 2)], frames, passes };
  })()`) as Promise<{ median: number; frames: number; passes: Record<string, number[]> }>);
  for (const { page } of pages) for (const kind of kinds) await block(page, kind, 1);
  for (let round = 0; round < rounds; round++) {
    for (const { page, name } of pages) {
      for (const kind of kinds) {
        // One untimed frame first: the first stepping frame after a paused block is a jump (no Worker), as is the reverse.
        await block(page, kind, 1);
        const before = cpuByKind(root);
        const { median, frames: drawn, passes } = await block(page, kind, frames);
        const after = cpuByKind(root);
        const row = `${name} ${kind}`;
        const r = rows.get(row) ?? { wall: [], gpu: [], renderer: [] };
        r.wall.push(median);
        r.gpu.push((after.gpu - before.gpu) / drawn);
        r.renderer.push((after.renderer - before.renderer) / drawn);
        rows.set(row, r);
        const p = passesByRow.get(row) ?? {};
        for (const [pass, ms] of Object.entries(passes)) (p[pass] ??= []).push(...ms);
        passesByRow.set(row, p);
      }
    }
  }
  for (const { page } of pages) await page.close();
  const med = (v: number[]) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
  console.log(`median of ${rounds} interleaved blocks of ${frames} frames (each block's figure in brackets):`);
  for (const [row, r] of rows) {
    const p = Object.entries(passesByRow.get(row) ?? {}).map(([name, ms]) => `${name} ${med(ms).toFixed(0)}`).join(', ');
    console.log(`  ${row.padEnd(34)} wall ${med(r.wall).toFixed(0)} [${r.wall.map((v) => v.toFixed(0)).join(' ')}]  gpu ${med(r.gpu).toFixed(0)} [${r.gpu.map((v) => v.toFixed(0)).join(' ')}]  renderer ${med(r.renderer).toFixed(0)} [${r.renderer.map((v) => v.toFixed(0)).join(' ')}]${p ? `  passes: ${p}` : ''}`);
  }
} finally {
  await harness.close();
}
