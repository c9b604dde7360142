import { describe, expect, it } from 'vitest';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { TILING_VIEW, tilingMetresPerPixel, tilingQuery } from './lightViews';
import { autocorrelation, peakBeyond, type Autocorrelation } from '../../support/autocorrelation';
import { highPass } from '../../support/highPass';
import { pngLuminances } from '../../support/luminance';
import { foamMask, solidFoamLevels } from './foamMeasure';

/**
 * No tile shows in the foam: seen from 400 m straight above, the foam mask (the pixels that read
 * as white foam, foamMeasure.ts) does not correlate with itself beyond 0.05 at any lag longer than the whitecaps
 * and their groups (50 m). The autocorrelation is averaged over four instants 30 s apart, so
 * that a repeat, which is there at every instant, stands out of the scatter of a finite
 * picture, which is not; and over each lag's 3 × 3 neighbourhood (tests/support/autocorrelation.ts).
 * Measured at 10 and 15 m/s (at 20 m/s whitecaps line up along crests a few hundred metres long:
 * a correlation that is the sea's, not the tiles').
 */
const harness = useHarness();
const SOLID_FOAM = solidFoamLevels(TILING_VIEW.sunElevation);
const MIN_LAG_METRES = 50;
const LIMIT = 0.05;

// The picture's own pattern: the luminance less its mean over a box this wide on each side, so
// the glint's and the sky's broad gradients drop out; its repeats are looked for past this lag.
const DETAIL_BOX_METRES = 40;
const PICTURE_MIN_LAG_METRES = 100;

function whiteFoam(png: Buffer): Float64Array {
  return foamMask(png, SOLID_FOAM);
}

function pictureDetail(png: Buffer): Float64Array {
  const values = pngLuminances(png);
  highPass(values, TILING_VIEW.width, TILING_VIEW.height, Math.round(DETAIL_BOX_METRES / tilingMetresPerPixel()));
  return values;
}

interface Peak {
  rho: number;
  lag: [number, number];
}

function describePeak(peak: Peak): string {
  return `${peak.rho.toFixed(3)} at (${peak.lag.map((m) => m.toFixed(0)).join(', ')}) m`;
}

interface RepeatOptions {
  fixes?: Parameters<typeof window.oceano.debug.setShadingFixes>[0];
  extraQuery?: string;
  measure?: (png: Buffer) => Float64Array;
  minLagMetres?: number;
}

async function repeatPeak(windSpeed: number, fixed: boolean, extraQuery = ''): Promise<Peak> {
  return measuredPeak(windSpeed, { fixes: fixed ? undefined : { foamBreakup: false }, extraQuery });
}

async function measuredPeak(
  windSpeed: number,
  { fixes, extraQuery = '', measure = whiteFoam, minLagMetres = MIN_LAG_METRES }: RepeatOptions,
): Promise<Peak> {
  const { page } = await openOcean(harness, tilingQuery(windSpeed) + extraQuery, TILING_VIEW.width, TILING_VIEW.height);
  if (fixes) await page.evaluate((f) => window.oceano.debug.setShadingFixes(f), fixes);
  const correlations: Autocorrelation[] = [];
  for (const t of TILING_VIEW.times) {
    await page.evaluate((time) => {
      window.oceano.pause();
      window.oceano.setTime(time);
    }, t);
    correlations.push(autocorrelation(measure(await canvasPng(page)), TILING_VIEW.width, TILING_VIEW.height));
  }
  await page.close();
  const [first] = correlations;
  const mean: Autocorrelation = {
    maxX: first.maxX,
    maxY: first.maxY,
    at: (dx, dy) => correlations.reduce((sum, c) => sum + c.at(dx, dy), 0) / correlations.length,
  };
  const metres = tilingMetresPerPixel();
  const peak = peakBeyond(mean, minLagMetres / metres, 1);
  return { rho: peak.rho, lag: [peak.dx * metres, peak.dy * metres] };
}

describe('no tile period in the foam or the picture', () => {
  // Control: the breakup field repeating with the smallest tile peaks above it at its lattice.
  it('from 400 m above, no autocorrelation peak above 0.05 past 50 m at 10 and 15 m/s', { timeout: 600_000 }, async () => {
    for (const windSpeed of [10, 15]) {
      const peak = await repeatPeak(windSpeed, true);
      const control = await repeatPeak(windSpeed, false);
      const say = `${windSpeed} m/s: peak ${describePeak(peak)}; control ${describePeak(control)}`;
      console.log(`[oceano] ${say}`);
      expect(peak.rho, say).toBeLessThan(LIMIT);
      expect(control.rho, say).toBeGreaterThan(LIMIT);
    }
  });

  // What the gale lesson asks the student to see: without the wave groups (waveGroups=0) the
  // 15 m/s foam repeats with the tiles again (0.107 at 334 m when measured, with the groups 0.022).
  it('with the wave groups switched off, the 15 m/s foam repeats: a peak above 0.05 past 50 m', { timeout: 300_000 }, async () => {
    const peak = await repeatPeak(15, true, '&waveGroups=0');
    const say = `15 m/s without groups: peak ${describePeak(peak)}`;
    console.log(`[oceano] ${say}`);
    expect(peak.rho, say).toBeGreaterThan(LIMIT);
  });

  // The picture, not only the foam: far away the two shorter tiles are read twice and blended by
  // a rotation that turns with a field that never repeats (shaders/waves/fft.glsl fftBlendCopies).
  // At 15 m/s from 400 m the tiles' repeat measured 0.055 without the copies.
  // The picture's detail. Control: every tile read once peaks above it.
  it('from 400 m above at 15 m/s, the detail has no autocorrelation peak above 0.05 past 100 m', { timeout: 300_000 }, async () => {
    const picture = { measure: pictureDetail, minLagMetres: PICTURE_MIN_LAG_METRES };
    const peak = await measuredPeak(15, picture);
    const control = await measuredPeak(15, { ...picture, fixes: { tileCopies: false } });
    const say = `15 m/s picture detail: peak ${describePeak(peak)}; control ${describePeak(control)}`;
    console.log(`[oceano] ${say}`);
    expect(peak.rho, say).toBeLessThan(LIMIT);
    expect(control.rho, say).toBeGreaterThan(LIMIT);
  });
});
