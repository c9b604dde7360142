// Takes a screenshot of the built app: `tsx scripts/probes/screenshot.ts OUT.png "seed=1&t=10" [width] [height]`.
import { writeFileSync } from 'node:fs';
import { canvasPng, openOcean, startHarness } from '../../tests/browser/harness';

const [out = 'shot.png', query = 't=10', width = '1280', height = '720'] = process.argv.slice(2);
const harness = await startHarness();
try {
  const { page, consoleErrors } = await openOcean(harness, query, Number(width), Number(height));
  const full = process.env.FULL_PAGE === '1';
  const png = full ? Buffer.from(await page.screenshot({ type: 'png' })) : await canvasPng(page);
  writeFileSync(out, png);
  const stats = await page.evaluate(() => window.oceano.stats());
  console.log(JSON.stringify({ out, stats, consoleErrors }));
} finally {
  await harness.close();
}
