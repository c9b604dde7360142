import { writeFileSync } from 'node:fs';
import { screenshotCanvas, startHarness } from '../tests/browser/harness';
const [w = '960', h = '540', ...jobs] = process.argv.slice(2);
const harness = await startHarness();
try {
  for (const job of jobs) {
    const [out, query] = job.split('|');
    const page = await harness.browser.newPage();
    page.setDefaultTimeout(300_000);
    const errors: string[] = [];
    page.on('console', (m) => { if (m.type() === 'error' || m.text().startsWith('[look]')) errors.push(m.text()); });
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.setViewport({ width: Number(w), height: Number(h), deviceScaleFactor: 1 });
    const t0 = Date.now();
    await page.goto(`${harness.baseUrl}?${query}`, { waitUntil: 'load', timeout: 300_000 });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    const t1 = Date.now();
    await page.evaluate(() => window.oceano.renderFrame());
    writeFileSync(out, await screenshotCanvas(page));
    const stats = await page.evaluate(() => window.oceano.stats());
    console.log(JSON.stringify({ out, loadMs: t1 - t0, frameMs: stats.frameMs, cpuMs: stats.cpuMs, boatMs: stats.boatMs, errors }));
    await page.close();
  }
} finally {
  await harness.close();
}
