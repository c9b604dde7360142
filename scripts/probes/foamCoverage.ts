// Prints the share of near-white pixels seen from 150 m above at 10, 15 and 20 m/s (the mean of
// four instants, and each), against Monahan's whitecap coverage. `tsx scripts/probes/foamCoverage.ts [out-dir] ["&more=query"]`
// also writes the frames; the second argument is added to the view's query (e.g. "&waveGroups=0").
import { writeFileSync } from 'node:fs';
import { canvasPng, openOcean, startHarness } from '../../tests/browser/harness';
import { measureFoam, solidFoamLevels } from '../../tests/browser/light/foamMeasure';
import { FOAM_VIEW, foamQuery } from '../../tests/browser/light/lightViews';
import { whitecapCoverage } from '../../src/sim/waves/fft/whitecaps';

const out = process.argv[2] || undefined;
const extraQuery = process.argv[3] ?? '';
const harness = await startHarness();
try {
  for (const wind of [10, 15, 20]) {
    const { page } = await openOcean(harness, foamQuery(wind) + extraQuery, FOAM_VIEW.width, FOAM_VIEW.height);
    const white: number[] = [];
    for (const t of FOAM_VIEW.times) {
      await page.evaluate((time) => {
        window.oceano.pause();
        window.oceano.setTime(time);
      }, t);
      const png = await canvasPng(page);
      if (out) writeFileSync(`${out}/foam-${wind}-t${t}.png`, png);
      white.push(measureFoam(png, solidFoamLevels(FOAM_VIEW.sunElevation)).white);
    }
    const mean = white.reduce((a, b) => a + b, 0) / white.length;
    console.log(
      JSON.stringify({ wind, white: mean, instants: white, monahan: whitecapCoverage(wind), ratio: mean / whitecapCoverage(wind) }),
    );
    await page.close();
  }
} finally {
  await harness.close();
}
