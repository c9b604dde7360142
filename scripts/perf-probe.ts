import { openOcean, startHarness } from './browserHarness';
const harness = await startHarness();
const { page } = await openOcean(harness, process.argv[2] ?? 't=10', Number(process.argv[3] ?? 1280), Number(process.argv[4] ?? 720));
const r = await page.evaluate(() => { const o = window.oceano; const ts: number[] = []; for (let i = 0; i < 15; i++) { const s = performance.now(); o.renderFrame(); ts.push(performance.now() - s); } ts.sort((a,b)=>a-b); return { med: ts[7], stats: o.stats() }; });
console.log(JSON.stringify(r));
await harness.close();
