import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from '../harness';
import type { ShadingFixes } from '../../../src/app/debug/shadingFaults';
import { useHarness } from '../useHarness';
import { glintWidth, meanChange } from './glintMeasure';
import { GLINT_VIEW, HORIZON_VIEW, glintQuery, horizonQuery } from './lightViews';

/**
 * The sun's glint follows Cox & Munk on every wave model: its width at 15 m/s against 5 m/s
 * is √(σ²(15)/σ²(5)) = √(0.0798/0.0286) = 1.67. Tolerance: the range Cox & Munk's own
 * scatter of ±0.004 on σ² allows, √(0.0758/0.0326) = 1.52 to √(0.0838/0.0246) = 1.85, its
 * lower end taken down to 1.50 because the picture's core clips at the display's white: the
 * narrower, brighter 5 m/s glint is measured wider than it is (docs/light-sun-and-sky.md,
 * "Measured: the glint's width, 5 against 15 m/s").
 * And the far sea does not sparkle: between two frames 1/60 s apart, the band just below
 * the horizon changes by less than FLICKER_BOUND on every model, and on the FFT sea, whose
 * near sea moves fastest, by less than the sea near the eye.
 */
const harness = useHarness();
const COX_MUNK_RATIO = [1.5, 1.85] as const;
/**
 * Mean change of the far band's luminance (0–255) between two frames 1/60 s apart, 10 m/s.
 * Measured: FFT 0.71 (its near band 1.77), seed 0.26, Gerstner 0.24; the fixed highlight on
 * the FFT sea 7.05 (near 1.95). The bound lies above the three by 29 % at least.
 */
const FLICKER_BOUND = 1.0;

async function frozenAt(page: Page, t: number): Promise<Buffer> {
  await page.evaluate((t) => {
    window.oceano.pause();
    window.oceano.setTime(t);
  }, t);
  return canvasPng(page);
}

/** The glint's width at 15 m/s over its width at 5 m/s, with `faults` planted (none: as it ships). */
async function glintRatio(faults: Partial<ShadingFixes> | null, waves: 'fft' | 'seed' | 'gerstner' = 'fft'): Promise<number> {
  const widths: number[] = [];
  for (const wind of [5, 15]) {
    const { page } = await openOcean(harness, glintQuery(wind, waves), GLINT_VIEW.width, GLINT_VIEW.height);
    if (faults) await page.evaluate((f) => window.oceano.debug.setShadingFixes(f), faults);
    widths.push(glintWidth(await frozenAt(page, GLINT_VIEW.t), GLINT_VIEW.seaTop, GLINT_VIEW.height));
    await page.close();
  }
  return widths[1] / widths[0];
}

async function flicker(fixed: boolean, waves: 'fft' | 'seed' | 'gerstner' = 'fft'): Promise<{ far: number; near: number }> {
  const { page } = await openOcean(harness, horizonQuery(10, waves), HORIZON_VIEW.width, HORIZON_VIEW.height);
  if (!fixed) await page.evaluate(() => window.oceano.debug.setShadingFixes({ slopeRoughness: false }));
  const a = await frozenAt(page, HORIZON_VIEW.t);
  const b = await frozenAt(page, HORIZON_VIEW.t + 1 / 60);
  await page.close();
  return {
    far: meanChange(a, b, HORIZON_VIEW.farBand[0], HORIZON_VIEW.farBand[1]),
    near: meanChange(a, b, HORIZON_VIEW.nearBand[0], HORIZON_VIEW.nearBand[1]),
  };
}

describe('the glint follows Cox & Munk', () => {
  it('widens 1.52–1.85× from 5 to 15 m/s; control: the fixed highlight on every slope does not', { timeout: 240_000 }, async () => {
    const ratio = await glintRatio(null);
    console.log(`[oceano] FFT glint, 15 against 5 m/s: ${ratio.toFixed(3)}`);
    expect(ratio).toBeGreaterThan(COX_MUNK_RATIO[0]);
    expect(ratio).toBeLessThan(COX_MUNK_RATIO[1]);
    const control = await glintRatio({ slopeRoughness: false });
    expect(control).toBeLessThan(COX_MUNK_RATIO[0]);
  });

  // The seed's and Gerstner's normals show their own swell, ripples or trochoids; the rest of
  // Cox & Munk's σ² is the same Beckmann roughness. Control: one roughness at every wind (the
  // fixed highlight is no control for Gerstner: its trochoids lengthen with the wind, and
  // that alone widened the old highlight 1.6×).
  for (const waves of ['seed', 'gerstner'] as const) {
    it(`on the ${waves} sea too; control: a 10 m/s sea's roughness at every wind does not widen`, { timeout: 240_000 }, async () => {
      const ratio = await glintRatio(null, waves);
      console.log(`[oceano] ${waves} glint, 15 against 5 m/s: ${ratio.toFixed(3)}`);
      expect(ratio).toBeGreaterThan(COX_MUNK_RATIO[0]);
      expect(ratio).toBeLessThan(COX_MUNK_RATIO[1]);
      const control = await glintRatio({ windRoughness: false }, waves);
      expect(control).toBeLessThan(COX_MUNK_RATIO[0]);
    });
  }

  // And by less than the near sea on the FFT sea. Control: the fixed highlight flickers more.
  it(
    `the far sea changes by at most ${FLICKER_BOUND} levels between frames 1/60 s apart, on every model`,
    { timeout: 300_000 },
    async () => {
      for (const waves of ['fft', 'seed', 'gerstner'] as const) {
        const fixed = await flicker(true, waves);
        console.log(`[oceano] ${waves} flicker, mean Δ levels over 1/60 s: far ${fixed.far.toFixed(2)}, near ${fixed.near.toFixed(2)}`);
        expect(fixed.far).toBeLessThan(FLICKER_BOUND);
        if (waves === 'fft') expect(fixed.far).toBeLessThan(fixed.near);
      }
      const control = await flicker(false);
      console.log(`[oceano] fft flicker with the fixed highlight: far ${control.far.toFixed(2)}, near ${control.near.toFixed(2)}`);
      expect(control.far).toBeGreaterThan(FLICKER_BOUND);
      expect(control.far).toBeGreaterThan(control.near);
    },
  );
});
