// Prints the light's figures on the built app: the glint's spread at 5 and 15 m/s (an FFT sea
// seen toward a 25° sun from 20 m up) and the horizon flicker (10 m/s, eye 10 m up, two frames
// 1/60 s apart). `tsx scripts/probes/lightFigures.ts [out-dir]` also writes the frames.
import { writeFileSync } from 'node:fs';
import { canvasPng, openOcean, startHarness } from '../../tests/browser/harness';
import { glintWidth, meanChange } from '../../tests/browser/light/glintMeasure';
import { GLINT_VIEW, HORIZON_VIEW, glintQuery, horizonQuery } from '../../tests/browser/light/lightViews';

const out = process.argv[2];
const harness = await startHarness();
try {
  const spreads: Record<string, number> = {};
  for (const wind of [5, 15]) {
    const { page } = await openOcean(harness, glintQuery(wind), GLINT_VIEW.width, GLINT_VIEW.height);
    await page.evaluate((t) => {
      window.oceano.pause();
      window.oceano.setTime(t);
    }, GLINT_VIEW.t);
    const png = await canvasPng(page);
    if (out) writeFileSync(`${out}/glint-${wind}.png`, png);
    spreads[wind] = glintWidth(png, GLINT_VIEW.seaTop, GLINT_VIEW.height);
    await page.close();
  }
  const { page } = await openOcean(harness, horizonQuery(10), HORIZON_VIEW.width, HORIZON_VIEW.height);
  const frames = [];
  for (const t of [HORIZON_VIEW.t, HORIZON_VIEW.t + 1 / 60]) {
    await page.evaluate((t) => {
      window.oceano.pause();
      window.oceano.setTime(t);
    }, t);
    frames.push(await canvasPng(page));
  }
  if (out) frames.forEach((f, i) => writeFileSync(`${out}/horizon-${i}.png`, f));
  const [a, b] = frames;
  const far = meanChange(a, b, HORIZON_VIEW.farBand[0], HORIZON_VIEW.farBand[1]);
  const near = meanChange(a, b, HORIZON_VIEW.nearBand[0], HORIZON_VIEW.nearBand[1]);
  console.log(
    JSON.stringify({ width5: spreads[5], width15: spreads[15], ratio: spreads[15] / spreads[5], far, near, farOverNear: far / near }),
  );
} finally {
  await harness.close();
}
