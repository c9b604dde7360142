import { describe, expect, it } from 'vitest';
import { coxMunkSlopeVariance, seaSlopeVariance, windAtHeight } from '../../../../src/sim/optics/coxMunk';
import {
  exponentialIntegral,
  piersonMoskowitzSlopeVarianceUpTo,
  resolvedShare,
  slopeVarianceUpTo,
  SUN_DISC_SLOPE_VARIANCE,
  unresolvedSlopeVariance,
} from '../../../../src/sim/optics/resolvedSlopes';
import { piersonMoskowitz } from '../../../../src/sim/waves/spectra/piersonMoskowitz';

/**
 * Cox & Munk 1954 (J. Opt. Soc. Am. 44, 838, clean surface): σ² = 0.003 + 5.12·10⁻³ U₁₂.₅,
 * written out by hand: 0.0286 at 5 m/s, 0.0542 at 10, 0.0798 at 15, so the glint's width at
 * 15 m/s is √(0.0798/0.0286) = 1.670 times its width at 5 m/s.
 */
const PUBLISHED: [number, number][] = [
  [5, 0.0286],
  [10, 0.0542],
  [15, 0.0798],
];

function matchesCoxMunk(variance: (u: number) => number): boolean {
  return PUBLISHED.every(([u, s]) => Math.abs(variance(u) - s) < 5e-5);
}

describe('Cox & Munk mean-square slope', () => {
  it('is 0.0286, 0.0542, 0.0798 at U₁₂.₅ = 5, 10, 15 m/s; control: a slope law in U² fails', () => {
    expect(matchesCoxMunk(coxMunkSlopeVariance)).toBe(true);
    expect(matchesCoxMunk((u) => 0.003 + (5.12e-3 * u * u) / 10)).toBe(false);
    expect(matchesCoxMunk((u) => 5.12e-3 * u)).toBe(false);
    expect(Math.sqrt(coxMunkSlopeVariance(15) / coxMunkSlopeVariance(5))).toBeCloseTo(1.67, 3);
  });

  it('takes U₁₂.₅ = 1.0201 U₁₀ from the log profile (C_D = 1.3·10⁻³, κ = 0.4); control: U₁₀ used as is fails', () => {
    expect(windAtHeight(10, 12.5)).toBeCloseTo(10.201, 3);
    expect(windAtHeight(10, 10)).toBe(10);
    // U₁₉.₅ by the same profile: 1.060 U₁₀.
    expect(windAtHeight(10, 19.5)).toBeCloseTo(10.602, 2);
    const expected = 0.003 + 5.12e-3 * 10.201;
    expect(seaSlopeVariance(10)).toBeCloseTo(expected, 5);
    expect(Math.abs(coxMunkSlopeVariance(10) - expected)).toBeGreaterThan(5e-4);
  });
});

describe('slope variance a spectrum resolves', () => {
  it('E₁ has its tabulated values (Abramowitz & Stegun table 5.1); control: the series without its log term fails', () => {
    const table: [number, number][] = [
      [0.1, 1.822924],
      [0.5, 0.5597736],
      [1, 0.2193839],
      [2, 0.04890051],
      [5, 0.001148296],
    ];
    for (const [x, e] of table) expect(exponentialIntegral(x) / e).toBeCloseTo(1, 5);
    expect(Math.abs(exponentialIntegral(0.1) + Math.log(0.1) - 1.822924)).toBeGreaterThan(0.1);
  });

  it('PM in closed form equals the integral of k² S(k) from the spectrum itself; control: α/2 instead of α/4 fails', () => {
    for (const wind of [5, 10, 20]) {
      for (const kCut of [0.5, 6.28, 50]) {
        const numeric = slopeVarianceUpTo((w) => piersonMoskowitz(w, wind), kCut);
        const closed = piersonMoskowitzSlopeVarianceUpTo(wind, kCut);
        expect(closed / numeric).toBeCloseTo(1, 4);
        expect(Math.abs((2 * closed) / numeric - 1)).toBeGreaterThan(0.5);
      }
    }
  });

  it('grows by α/2 = 0.00405 per e-fold of k in the tail, whatever the wind', () => {
    for (const wind of [5, 10, 20]) {
      const step = piersonMoskowitzSlopeVarianceUpTo(wind, 20 * Math.E) - piersonMoskowitzSlopeVarianceUpTo(wind, 20);
      expect(step).toBeCloseTo(0.00405, 5);
    }
  });

  it('PM up to 1 m waves resolves about a third of Cox–Munk at 10 m/s and less of it as the wind rises', () => {
    const k = 2 * Math.PI;
    const share = (u: number) => piersonMoskowitzSlopeVarianceUpTo(u, k) / seaSlopeVariance(u);
    expect(share(10)).toBeGreaterThan(0.25);
    expect(share(10)).toBeLessThan(0.45);
    expect(share(15)).toBeLessThan(share(10));
  });

  // Control: Nyquist forgotten.
  it('a band is resolved while its shortest wave spans two footprints and gone once its longest does', () => {
    expect(resolvedShare(0.1, 1, 4)).toBe(1);
    expect(resolvedShare(0.5, 1, 4)).toBe(1);
    expect(resolvedShare(1, 1, 4)).toBeCloseTo(0.5, 12);
    expect(resolvedShare(2, 1, 4)).toBe(0);
    const withoutNyquist = (f: number, s: number, l: number) => Math.min(1, Math.max(0, Math.log(l / f) / Math.log(l / s)));
    expect(withoutNyquist(1, 1, 4)).not.toBeCloseTo(resolvedShare(1, 1, 4), 3);
  });

  it('the unresolved part is the total less the resolved, and never below the sun disc', () => {
    expect(unresolvedSlopeVariance(0.0542, 0.02)).toBeCloseTo(0.0342, 12);
    expect(unresolvedSlopeVariance(0.01, 0.02)).toBe(SUN_DISC_SLOPE_VARIANCE);
    expect(SUN_DISC_SLOPE_VARIANCE).toBeCloseTo(2.7e-6, 7);
  });
});

describe('cascade wavelengths for the glint', () => {
  // 4 texels of it; the smallest runs to 2 texels.
  it('the bands touch: each tile’s longest wave is the next larger tile’s shortest', async () => {
    const { cascadeLayout } = await import('../../../../src/sim/waves/fft/cascades');
    const { cascadeWavelengths } = await import('../../../../src/sim/optics/resolvedSlopes');
    const n = 128;
    const cascades = cascadeLayout(87.6, n);
    const bands = cascades.map((c) => cascadeWavelengths(c, n));
    expect(bands[0].longest).toBeCloseTo(cascades[0].size, 9);
    expect(bands[0].shortest).toBeCloseTo((4 * cascades[0].size) / n, 9);
    expect(bands[1].longest).toBeCloseTo(bands[0].shortest, 9);
    expect(bands[2].longest).toBeCloseTo(bands[1].shortest, 9);
    expect(bands[2].shortest).toBeCloseTo((2 * cascades[2].size) / n, 9);
  });
});
