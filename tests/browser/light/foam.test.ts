import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { measureFoam, solidFoamLevels, type FoamPicture } from './foamMeasure';
import { FOAM_VIEW, foamQuery } from './lightViews';
import { whitecapCoverage } from '../../../src/sim/waves/fft/whitecaps';

/**
 * Foam seen from 150 m above (the sun 30° high, its glint outside the frame):
 * - covers what Monahan & O'Muircheartaigh measured, W = 3.84·10⁻⁶ U^3.41 (1.0 %, 3.9 %,
 *   10.5 % at 10, 15, 20 m/s), within ±30 %: the share of the picture's pixels that read as
 *   white foam, averaged over four instants, not the share of the Jacobian below its
 *   threshold; so it does with the whitecaps' wave groups switched off (waveGroups=0);
 * - is as bright as its measured reflectance makes it under this sun and sky, and tinted blue
 *   by the sky as that light is (tests/browser/light/foamMeasure.ts solidFoamLevels).
 */
const harness = useHarness();
const TOLERANCE = 0.3;
const SOLID = solidFoamLevels(FOAM_VIEW.sunElevation);
// Measured at 20 m/s: the peak 169.3 levels where solid foam's red is 172.5, blue over red 25.8
// where it is 26.8. Controls: with the albedo drawn before, the peak at 185.0; lit by a grey sky,
// blue over red −6.5.
const MAX_PEAK_OFF = 6;
const MAX_TINT_OFF = 6;

async function foamAt(page: Page): Promise<FoamPicture[]> {
  const pictures: FoamPicture[] = [];
  for (const t of FOAM_VIEW.times) {
    await page.evaluate((time) => {
      window.oceano.pause();
      window.oceano.setTime(time);
    }, t);
    pictures.push(measureFoam(await canvasPng(page), SOLID));
  }
  return pictures;
}

const mean = (values: number[]): number => values.reduce((a, b) => a + b, 0) / values.length;

async function coverageRatios(fixed: boolean, extraQuery = ''): Promise<number[]> {
  const ratios: number[] = [];
  for (const wind of [10, 15, 20]) {
    const { page } = await openOcean(harness, foamQuery(wind) + extraQuery, FOAM_VIEW.width, FOAM_VIEW.height);
    if (!fixed) await page.evaluate(() => window.oceano.debug.setShadingFixes({ foamCoverage: false }));
    ratios.push(mean((await foamAt(page)).map((p) => p.white)) / whitecapCoverage(wind));
    await page.close();
  }
  return ratios;
}

describe('foam from above', () => {
  // Control: the foam left behind drawn solid white is 1.5–2.3 W.
  it('near-white share within ±30 % of W at 10, 15 and 20 m/s, with wave groups and without', { timeout: 240_000 }, async () => {
    const ratios = await coverageRatios(true);
    console.log(`[oceano] foam coverage / Monahan's W at 10, 15, 20 m/s: ${ratios.map((r) => r.toFixed(2)).join(', ')}`);
    for (const ratio of ratios) expect(Math.abs(ratio - 1), ratios.map((r) => r.toFixed(2)).join(', ')).toBeLessThan(TOLERANCE);
    const withoutGroups = await coverageRatios(true, '&waveGroups=0');
    console.log(`[oceano] without wave groups (waveGroups=0): ${withoutGroups.map((r) => r.toFixed(2)).join(', ')}`);
    for (const ratio of withoutGroups)
      expect(Math.abs(ratio - 1), `without groups: ${withoutGroups.map((r) => r.toFixed(2)).join(', ')}`).toBeLessThan(TOLERANCE);
    const control = await coverageRatios(false);
    console.log(`[oceano] control, foam left behind drawn solid: ${control.map((r) => r.toFixed(2)).join(', ')}`);
    expect(Math.min(...control), control.map((r) => r.toFixed(2)).join(', ')).toBeGreaterThan(1 + TOLERANCE);
  });

  // Under this sun and sky. Controls: the brighter albedo drawn before, a grey sky's light.
  it('is as bright and as blue as its measured reflectance makes solid foam, at 20 m/s', { timeout: 120_000 }, async () => {
    const { page } = await openOcean(harness, foamQuery(20), FOAM_VIEW.width, FOAM_VIEW.height);
    const measure = async () => {
      const pictures = await foamAt(page);
      return { peak: mean(pictures.map((p) => p.peak)), tint: mean(pictures.map((p) => p.blueOverRed)) };
    };
    const measured = await measure();
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ foamReflectance: false }));
    const brighter = await measure();
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ foamReflectance: true, foamSkyColour: false }));
    const greySky = await measure();
    await page.close();
    const expected = { peak: Math.min(...SOLID), tint: SOLID[2] - SOLID[0] };
    const line = (m: { peak: number; tint: number }) => `peak ${m.peak.toFixed(1)}, blue over red ${m.tint.toFixed(1)}`;
    console.log(
      `[oceano] solid foam from its reflectance: ${line(expected)}; drawn: ${line(measured)}; with the albedo before: ${line(brighter)}; lit by a grey sky: ${line(greySky)}`,
    );
    expect(Math.abs(measured.peak - expected.peak), line(measured)).toBeLessThanOrEqual(MAX_PEAK_OFF);
    expect(Math.abs(measured.tint - expected.tint), line(measured)).toBeLessThanOrEqual(MAX_TINT_OFF);
    expect(Math.abs(brighter.peak - expected.peak), line(brighter)).toBeGreaterThan(MAX_PEAK_OFF);
    expect(Math.abs(greySky.tint - expected.tint), line(greySky)).toBeGreaterThan(MAX_TINT_OFF);
  });
});
