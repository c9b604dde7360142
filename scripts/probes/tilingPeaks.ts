// The largest autocorrelation past 50 m of the sea seen straight down, averaged over four
// instants 30 s apart, as tests/browser/light/tiling.test.ts measures it, at any height,
// wind and measure: `tsx scripts/probes/tilingPeaks.ts ALTITUDE WIND foam|picture [breakupOff|groupsOff|-] [MIN_LAG_METRES]`.
// breakupOff: the breakup field repeating with the smallest tile (the test's control); groupsOff: waveGroups=0.
// WAVES=seed|gerstner measures another wave model (default fft); EXTRA_QUERY is added to the query.
// "foam": the pixels that read as white foam (tests/browser/light/foamMeasure.ts foamMask); "picture": the luminance itself; "detail": the luminance less
// its mean over a box 2·HIGHPASS_METRES wide (default 40 m), so the glint's and the sky's broad
// gradients drop out and what is left is the waves' own pattern.
import { canvasPng, openOcean, startHarness } from '../../tests/browser/harness';
import { autocorrelation, peakBeyond, type Autocorrelation } from '../../tests/support/autocorrelation';
import { highPass } from '../../tests/support/highPass';
import { pngLuminances } from '../../tests/support/luminance';
import { foamMask, solidFoamLevels } from '../../tests/browser/light/foamMeasure';

const [altitude = '1500', wind = '10', measure = 'foam', fault = '', minLag = '50'] = process.argv.slice(2);
const width = 640;
const height = 360;
const metresPerPixel = (2 * Number(altitude) * Math.tan((27.5 * Math.PI) / 180)) / height;
const harness = await startHarness();
try {
  const { page } = await openOcean(
    harness,
    `waves=${process.env.WAVES ?? 'fft'}&windSpeed=${wind}&sunElevation=30&t=10&cam=0,${altitude},0,0,0,-0.01${fault === 'groupsOff' ? '&waveGroups=0' : ''}${process.env.EXTRA_QUERY ?? ''}`,
    width,
    height,
  );
  if (fault === 'breakupOff') await page.evaluate(() => window.oceano.debug.setShadingFixes({ foamBreakup: false }));
  const correlations: Autocorrelation[] = [];
  for (const t of [10, 40, 70, 100]) {
    await page.evaluate((time) => {
      window.oceano.pause();
      window.oceano.setTime(time);
    }, t);
    const png = await canvasPng(page);
    const values = measure === 'foam' ? foamMask(png, solidFoamLevels(30)) : pngLuminances(png);
    if (measure === 'detail') highPass(values, width, height, Math.round(Number(process.env.HIGHPASS_METRES ?? 40) / metresPerPixel));
    correlations.push(autocorrelation(values, width, height));
  }
  const [first] = correlations;
  const mean: Autocorrelation = {
    maxX: first.maxX,
    maxY: first.maxY,
    at: (dx, dy) => correlations.reduce((sum, c) => sum + c.at(dx, dy), 0) / correlations.length,
  };
  const peak = peakBeyond(mean, Number(minLag) / metresPerPixel, 1);
  console.log(
    `${altitude} m, ${wind} m/s, ${measure}${fault && fault !== '-' ? ` (${fault})` : ''}, past ${minLag} m: peak ${peak.rho.toFixed(3)} at (${(peak.dx * metresPerPixel).toFixed(0)}, ${(peak.dy * metresPerPixel).toFixed(0)}) m; ${metresPerPixel.toFixed(2)} m a pixel`,
  );
} finally {
  await harness.close();
}
