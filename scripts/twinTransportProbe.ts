/**
 * The FFT twin's three Worker transports side by side in one run (a measurement, asserts
 * nothing): one page each, the same build and server (cross-origin isolated, fine timers),
 * the transport forced per page through globalThis.__twinTransport (fftWaveView.ts, this
 * commit only). Blocks of 30 looped frames, interleaved page by page (A, B, C, A, B, C, …),
 * reading stats().twinMs (mean main-thread ms per frame of the twin) and cpuMs (median
 * update step) at the end of each block; then, as the bench takes cpuMs, 30 paused frames.
 *   npx vite build --logLevel warn && npx tsx scripts/twinTransportProbe.ts [blocks] [query]
 */
import { loadavg } from 'node:os';
import type { Page } from 'puppeteer';
import { startLongHarness } from './browserHarness';

const blocks = Number(process.argv[2] ?? 5);
const query = process.argv[3] ?? 't=10&waves=fft';
const TRANSPORTS = ['shared-memory', 'messages', 'main-thread'] as const;
const BLOCK = 30;
const [WIDTH, HEIGHT] = (process.env.PROBE_SIZE ?? '640x360').split('x').map(Number);
const harness = await startLongHarness();

async function open(transport: string): Promise<Page> {
  const page = await harness.browser.newPage();
  page.setDefaultTimeout(600_000);
  await page.evaluateOnNewDocument((t) => ((globalThis as { __twinTransport?: string }).__twinTransport = t), transport);
  await page.setViewport({ width: WIDTH, height: HEIGHT, deviceScaleFactor: 1 });
  await page.goto(`${harness.baseUrl}?${query}`, { waitUntil: 'load' });
  await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
  await page.evaluate(() => window.oceano.ready);
  return page;
}

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
    return { twinMs: s.twinMs, cpuMs: s.cpuMs, transport: s.twin && s.twin.transport, received: s.twin ? s.twin.fieldsReceived : 0, isolated: window.crossOriginIsolated };
  })()`) as Promise<{ twinMs: number | null; cpuMs: number; transport: string | null; received: number; isolated: boolean }>;

const pausedCpu = (page: Page) =>
  page.evaluate(`(() => {
    const o = window.oceano;
    o.pause();
    for (let i = 0; i < ${BLOCK + 10}; i++) o.renderFrame();
    return o.stats().cpuMs;
  })()`) as Promise<number>;

const mean = (v: number[]) => v.reduce((a, c) => a + c, 0) / v.length;
const median = (v: number[]) => [...v].sort((a, b) => a - b)[v.length >> 1];
try {
  console.log(`load average at start: ${loadavg().map((l) => l.toFixed(2)).join(' ')}`);
  const pages: Page[] = [];
  for (const t of TRANSPORTS) pages.push(await open(t));
  const twin: number[][] = TRANSPORTS.map(() => []);
  const cpu: number[][] = TRANSPORTS.map(() => []);
  const paused: number[][] = TRANSPORTS.map(() => []);
  const seen: string[] = TRANSPORTS.map(() => '');
  for (let b = 0; b < blocks; b++) {
    for (let i = 0; i < TRANSPORTS.length; i++) {
      await pages[i].bringToFront();
      const r = await loopBlock(pages[i]);
      if (!r.isolated) throw new Error('Not cross-origin isolated: timers are coarse.');
      twin[i].push(r.twinMs ?? Number.NaN);
      cpu[i].push(r.cpuMs);
      seen[i] = `${r.transport} (${r.received} deliveries)`;
      paused[i].push(await pausedCpu(pages[i]));
    }
  }
  TRANSPORTS.forEach((t, i) => {
    console.log(`${t} [reported: ${seen[i]}]: twinMs mean ${mean(twin[i]).toFixed(3)} (blocks ${twin[i].map((v) => v.toFixed(3)).join(' ')}); looped cpuMs median ${median(cpu[i]).toFixed(3)} (${cpu[i].map((v) => v.toFixed(3)).join(' ')}); paused cpuMs median ${median(paused[i]).toFixed(3)} (${paused[i].map((v) => v.toFixed(3)).join(' ')})`);
  });
  console.log(`load average at end: ${loadavg().map((l) => l.toFixed(2)).join(' ')}`);
} finally {
  await harness.close();
}
