/**
 * Where stats().twinMs goes (waves=fft, the loop playing), part by part (a diagnostic: prints
 * numbers, asserts nothing). Needs a build with the timers of twinBreakdown.patch, which log
 * each frame's parts (heights, the Worker request inside them, receipts) to globalThis:
 *   git apply scripts/twinBreakdown.patch && npx vite build --outDir dist/instr && git checkout src
 *   npx vite build   (dist/ itself, which the preview serves)
 *   PROBE_BUILD=instr npx tsx scripts/twinBreakdown.ts [blocks]
 * Served with COOP + COEP (fine timers), as loopCostProbe.ts. Per block of 30 looped frames:
 * each part's mean per frame, each frame's total, and the receipts split into reading
 * event.data, adopting the fields, and posting the next request.
 */
import { loadavg } from 'node:os';
import { openOcean, startLongHarness } from './browserHarness';

const blocks = Number(process.argv[2] ?? 3);
const build = `${process.env.PROBE_BUILD ?? 'instr'}/`;
const query = process.env.PROBE_QUERY ?? 't=10&waves=fft';
const [WIDTH, HEIGHT] = (process.env.PROBE_SIZE ?? '1280x720').split('x').map(Number);
const harness = await startLongHarness();
try {
  console.log(`load ${loadavg().map((l) => l.toFixed(2)).join(' ')}`);
  const { page } = await openOcean(harness, query, WIDTH, HEIGHT, build, 600_000);
  for (let b = 0; b < blocks; b++) {
    const r = (await page.evaluate(`(async () => {
      const o = window.oceano;
      globalThis.__twinLog = []; globalThis.__recvLog = []; globalThis.__postLog = [];
      const first = o.activity().framesDrawn;
      o.play();
      await new Promise((resolve) => { const t = setInterval(() => { if (o.activity().framesDrawn - first < 30) return; clearInterval(t); resolve(); }, 2); });
      const s = o.stats();
      o.pause();
      return { twinMs: s.twinMs, log: globalThis.__twinLog.slice(-30), recv: globalThis.__recvLog, post: globalThis.__postLog };
    })()`)) as { twinMs: number; log: Record<string, number>[]; recv: number[][]; post: number[] };
    const keys = [...new Set(r.log.flatMap((f) => Object.keys(f)))];
    const mean = (k: string) => r.log.reduce((a, f) => a + (f[k] ?? 0), 0) / r.log.length;
    console.log(`block ${b}: posts ${r.post.length} mean ${(r.post.reduce((a, v) => a + v, 0) / r.post.length).toFixed(3)} max ${Math.max(...r.post).toFixed(2)}; twinMs ${r.twinMs.toFixed(3)}; per-frame means: ${keys.map((k) => `${k} ${mean(k).toFixed(3)}`).join(', ')}`);
    console.log(`  totals per frame: ${r.log.map((f) => f.total.toFixed(2)).join(' ')}`);
    const rm = (i: number) => (r.recv.reduce((a, v) => a + v[i], 0) / Math.max(1, r.recv.length)).toFixed(3);
    console.log(`  receipts ${r.recv.length}: mean data ${rm(0)} deliver ${rm(1)} flush ${rm(2)}; max ${Math.max(...r.recv.map((v) => v[0] + v[1] + v[2])).toFixed(2)}`);
  }
  console.log(`load ${loadavg().map((l) => l.toFixed(2)).join(' ')}`);
} finally {
  await harness.close();
}
