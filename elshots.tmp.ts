import { writeFileSync } from 'node:fs';
import { startHarness } from './tests/browser/harness';
import { recordedPage, viewsReady } from './tests/browser/pages';
const harness = await startHarness();
const { page, consoleErrors } = await recordedPage(harness, 1000, 800);
await page.goto(`${harness.baseUrl}fixtures/no-views.html`, { waitUntil: 'load' });
await page.evaluate((specs) => {
  for (const [id, width, settings] of specs as [string, number, Record<string, string>][]) {
    const view = document.createElement('oceano-view');
    view.id = id;
    view.style.width = `${width}px`;
    view.style.margin = '8px';
    for (const [name, value] of Object.entries({ t: '3', lang: 'en', ...settings })) view.setAttribute(name, value);
    document.body.append(view);
  }
}, JSON.parse(process.argv[2]));
await viewsReady(page);
await page.evaluate(async () => {
  for (const view of document.querySelectorAll('oceano-view')) {
    const o = (view as any).oceano;
    await o.loaded();
    if (o.getParams().physics) await o.debug.physicsRuns();
    o.renderFrame();
  }
});
writeFileSync(process.argv[3], await page.screenshot({ type: 'png', fullPage: true }));
console.log(consoleErrors);
await harness.close();
