// Prints the share of near-white pixels seen from 150 m above at 10, 15 and 20 m/s, against
// Monahan's whitecap coverage. `tsx scripts/probes/foamCoverage.ts [out-dir]` also writes the frames.
import { writeFileSync } from 'node:fs';
import { canvasPng, openOcean, startHarness } from '../../tests/browser/harness';
import { whiteShare } from '../../tests/browser/light/glintMeasure';
import { FOAM_VIEW, foamQuery } from '../../tests/browser/light/lightViews';
import { whitecapCoverage } from '../../src/sim/waves/fft/whitecaps';

const out = process.argv[2];
const harness = await startHarness();
try {
  for (const wind of [10, 15, 20]) {
    const { page } = await openOcean(harness, foamQuery(wind), FOAM_VIEW.width, FOAM_VIEW.height);
    await page.evaluate((t) => {
      window.oceano.pause();
      window.oceano.setTime(t);
    }, FOAM_VIEW.t);
    const png = await canvasPng(page);
    if (out) writeFileSync(`${out}/foam-${wind}.png`, png);
    console.log(JSON.stringify({ wind, white: whiteShare(png), monahan: whitecapCoverage(wind) }));
    await page.close();
  }
} finally {
  await harness.close();
}
