/**
 * Where the FFT view's frame goes (a benchmark: prints numbers, asserts nothing). On a machine
 * shared with other jobs wall times swing by 2×, so beside the median wall time of a frame it
 * prints the CPU time Chromium's processes spent on it (SwiftShader draws on the CPU, in the
 * GPU process: its CPU time is the frame's cost, whatever else the machine runs), for:
 *   paused:   the clock still (the scene alone: no FFT passes, no Worker),
 *   stepping: the clock moved 1/60 s before each frame, as the bench's FFT row (FFT passes,
 *             foam, the CPU twin's Worker in the renderer process),
 * and the default view beside it. `PROBE_BUILDS=dist-sub,...` also probes builds put under
 * dist/ (vite build --outDir dist/NAME), to compare variants in one run; `PROBE_ROUNDS=k` probes
 * every build k times, interleaved (A B A B …), and ends with each row's median GPU-process CPU
 * time over the rounds: on a loaded machine one round's figure moves by 15 % from minute to minute.
 * Caveat: each setTime also asks the app's loop for a redraw, drawn at the next animation frame
 * after the evaluate, so a stepping row's CPU figures may carry one more frame than they divide
 * by (+1/frames of a frame: measured +60 to +170 ms GPU CPU on the default view); fftGapProbe.ts
 * divides by the frames the app drew.
 * Run after `vite build`: npx tsx scripts/fftFrameProbe.ts [frames] [queries, ;-separated]
 */
import { openOcean, startHarness } from './browserHarness';
import { cpuByKind } from './procCpu';

const frames = Number(process.argv[2] ?? 8);
const queries = (process.argv[3] ?? 't=10;t=10&waves=fft').split(';');
const builds = ['', ...(process.env.PROBE_BUILDS ?? '').split(',').filter(Boolean).map((b) => `${b}/`)];
const rounds = Math.max(1, Number(process.env.PROBE_ROUNDS ?? 1));
/** Per row (build, query, paused or stepping): the GPU process's CPU ms per frame of each round. */
const gpuByRow = new Map<string, number[]>();

const harness = await startHarness();
const root = harness.browser.process()?.pid;
if (root === undefined) throw new Error('No browser process to measure.');
try {
  for (let round = 0; round < rounds; round++) for (const build of builds) {
    for (const query of queries) {
      const { page } = await openOcean(harness, query, 1280, 720, build, 600_000);
      for (const step of process.env.PROBE_PAUSED_ONLY ? [0] : [0, 1 / 60]) {
        // A string, not a function: tsx would wrap named helpers in a `__name` the page lacks.
        const run = (count: number) => page.evaluate(`(() => {
          const o = window.oceano;
          o.pause();
          const gl = o.three.renderer.getContext();
          const pixel = new Uint8Array(4);
          const times = [];
          for (let i = 0; i < ${count}; i++) {
            if (${step} > 0) o.setTime(10 + (window.__probeFrame = (window.__probeFrame ?? 0) + 1) * ${step});
            const start = performance.now();
            o.renderFrame();
            gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
            times.push(performance.now() - start);
          }
          times.sort((a, b) => a - b);
          return { median: times[Math.floor(times.length / 2)], cpuMs: o.stats().cpuMs };
        })()`) as Promise<{ median: number; cpuMs: number }>;
        await run(2);
        const before = cpuByKind(root);
        const { median, cpuMs } = await run(frames);
        const after = cpuByKind(root);
        const per = (k: string) => ((after[k] - before[k]) / frames).toFixed(0);
        const row = `${build || 'dist/'} ${query} ${step ? 'stepping' : 'paused  '}`;
        gpuByRow.set(row, [...(gpuByRow.get(row) ?? []), (after.gpu - before.gpu) / frames]);
        console.log(`${build || 'dist/'} ${query} ${step ? 'stepping' : 'paused  '}: wall median ${median.toFixed(0)} ms; CPU per frame: gpu ${per('gpu')} ms, renderer ${per('renderer')} ms; app cpuMs ${cpuMs.toFixed(2)}`);
      }
      const passes = (await page.evaluate(`window.oceano.debug.passTimings()`)) as { name: string; ms: number }[];
      console.log(`${build || 'dist/'} ${query} passes (wall, one frame): ${passes.map((p) => `${p.name} ${p.ms.toFixed(1)} ms`).join(', ')}`);
      await page.close();
    }
  }
  if (rounds > 1) {
    console.log(`GPU-process CPU ms per frame, median of ${rounds} rounds (each round's figure in brackets):`);
    for (const [row, values] of gpuByRow) {
      const sorted = [...values].sort((a, b) => a - b);
      console.log(`  ${row}: ${sorted[Math.floor(sorted.length / 2)].toFixed(0)} [${values.map((v) => v.toFixed(0)).join(', ')}]`);
    }
  }
} finally {
  await harness.close();
}
