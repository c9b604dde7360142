/**
 * The same view drawn by two builds, compared (a measurement: prints numbers, asserts nothing):
 * `npx tsx scripts/probes/buildDiff.ts VARIANT OUTDIR "query;query" [width] [height]` opens each query
 * in dist/ and in dist/VARIANT/ (vite build --outDir dist/VARIANT), writes both canvases, the
 * difference (tests/browser/imageCompare.ts's red ×8 map) and prints the difference in the
 * reference tests' terms. For shader variants that change the picture on purpose.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { describeDifference, measureDifference } from '../../tests/browser/imageCompare';
import { canvasPng, openOcean, startHarness } from '../../tests/browser/harness';

const [variant, outDir, queryList = 'preset=gale&t=10', width = '640', height = '360'] = process.argv.slice(2);
if (!variant || !outDir) throw new Error('usage: scripts/probes/buildDiff.ts VARIANT OUTDIR "query;query" [width] [height]');
mkdirSync(outDir, { recursive: true });
const harness = await startHarness();
try {
  for (const [q, query] of queryList.split(';').entries()) {
    const shots: Buffer[] = [];
    for (const build of ['', `${variant}/`]) {
      const { page } = await openOcean(harness, query, Number(width), Number(height), build, 600_000);
      const png = await canvasPng(page);
      writeFileSync(join(outDir, `${q}-${build ? variant : 'base'}.png`), png);
      shots.push(png);
      await page.close();
    }
    const d = measureDifference(shots[0], shots[1], join(outDir, `${q}-diff.png`));
    console.log(`${query} (${width}×${height}): ${describeDifference(d)}`);
  }
} finally {
  await harness.close();
}
