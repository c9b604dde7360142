import { writeFileSync } from 'node:fs';
import { openOcean, startHarness } from './tests/browser/harness';
const [outDir, sizeText, ...lessons] = process.argv.slice(2);
const [width, height] = sizeText.split('x').map(Number);
const harness = await startHarness();
for (const lesson of lessons) {
  const [id, language = 'en', extra = ''] = lesson.split(':');
  const { page, consoleErrors } = await openOcean(harness, `lesson=${id}&lang=${language}&t=5${extra ? '&' + extra : ''}`, width, height);
  await page.waitForSelector('.oceano-lesson-card:not([hidden])');
  await page.evaluate(() => window.oceano.loaded());
  await new Promise((r) => setTimeout(r, 500));
  await page.evaluate(() => window.oceano.renderFrame());
  const file = `${outDir}/${id}-${width}x${height}-${language}.png`;
  writeFileSync(file, await page.screenshot({ type: 'png' }));
  console.log(file, consoleErrors);
  await page.close();
}
await harness.close();
