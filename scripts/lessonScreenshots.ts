import { writeFileSync } from 'node:fs';
import { openOcean, startHarness } from '../tests/browser/harness';

/**
 * Screenshots of lessons as a user sees them (drawer, card and panel included), at a laptop's
 * and a phone's size in both languages, as JPEG for docs/figures:
 * `npx tsx scripts/lessonScreenshots.ts OUT_DIR lesson…` after `npx vite build`.
 */
const [outDir = 'lesson-screenshots', ...lessons] = process.argv.slice(2);
const SIZES = [
  { name: 'laptop', width: 1366, height: 768 },
  { name: 'phone', width: 390, height: 844 },
];

const harness = await startHarness();
try {
  for (const lesson of lessons.length > 0 ? lessons : ['swell']) {
    for (const language of ['en', 'es']) {
      for (const size of SIZES) {
        const { page, consoleErrors } = await openOcean(harness, `lesson=${lesson}&lang=${language}&t=5`, size.width, size.height);
        await page.waitForSelector('.oceano-lesson-card:not([hidden])');
        await page.evaluate(() => window.oceano.loaded());
        const file = `${outDir}/lesson-${lesson}-${size.name}-${language}.jpg`;
        writeFileSync(file, await page.screenshot({ type: 'jpeg', quality: 82 }));
        console.log(file, consoleErrors.length > 0 ? consoleErrors : '');
        await page.close();
      }
    }
  }
} finally {
  await harness.close();
}
