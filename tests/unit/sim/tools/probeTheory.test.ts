import { describe, expect, it } from 'vitest';
import { defaultParams } from '../../../../src/sim/params/params';
import { probeTheory, spectralMoment, spectralTheory, swellRecord } from '../../../../src/sim/tools/probeTheory';
import { meanUpCrossingPeriod } from '../../../../src/sim/tools/probeStatistics';
import { piersonMoskowitz, piersonMoskowitzM0, piersonMoskowitzPeak } from '../../../../src/sim/waves/spectra/piersonMoskowitz';
import { jonswapShape, jonswapWithShape } from '../../../../src/sim/waves/spectra/jonswap';

const pm = (u: number) => ({ density: (w: number) => piersonMoskowitz(w, u), peak: piersonMoskowitzPeak(u) });

describe('the probe’s theory for a spectral sea', () => {
  it('m₀ of Pierson–Moskowitz by quadrature equals its closed form', () => {
    for (const u of [5, 10, 20]) expect(spectralMoment(pm(u), 0) / piersonMoskowitzM0(u)).toBeCloseTo(1, 5);
  });

  it('Pierson–Moskowitz: Tz / Tp = (5π/4)^(−1/4) = 0.7104, and Hs = 0.21 U₁₉.₅²/g', () => {
    // From S ∝ ω⁻⁵ e^{−5/4 (ωp/ω)⁴}: m₀/m₂ = 1/(ωp² √(5π/4)), so Tz = Tp (5π/4)^(−1/4). DNV-RP-C205 (2010) §3.5.5 gives 0.7117 from its fit.
    const theory = spectralTheory(pm(10));
    expect(theory.kind).toBe('spectrum');
    if (theory.kind !== 'spectrum') return;
    expect(theory.period / theory.peakPeriod).toBeCloseTo((1.25 * Math.PI) ** -0.25, 4);
    expect(Math.abs(theory.period / theory.peakPeriod / 0.7117 - 1)).toBeLessThan(0.005);
    expect(theory.height / ((0.21 * (1.026 * 10) ** 2) / 9.81)).toBeCloseTo(1, 1);
  });

  it('JONSWAP (γ = 3.3): Tz / Tp within 1 % of DNV-RP-C205’s 0.6673 + 0.05037γ − 0.00623γ² + 0.0003341γ³ = 0.7777', () => {
    const { alpha, peak } = jonswapShape(10, 100_000);
    const theory = spectralTheory({ density: (w) => jonswapWithShape(w, alpha, peak), peak });
    const gamma = 3.3;
    const dnv = 0.6673 + 0.05037 * gamma - 0.00623 * gamma ** 2 + 0.0003341 * gamma ** 3;
    expect(theory.kind === 'spectrum' && Math.abs(theory.period / theory.peakPeriod / dnv - 1)).toBeLessThan(0.01);
    // Control: Pierson–Moskowitz's ratio is 9 % below it, outside the 1 %.
    expect(Math.abs(0.7104 / dnv - 1)).toBeGreaterThan(0.01);
  });

  it('the fft and gerstner seas get the spectrum’s theory', () => {
    const params = { ...defaultParams(), waves: 'fft' as const, windSpeed: 10, spectrum: 'pierson-moskowitz' as const };
    const theory = probeTheory(params, 3, 4, [0, 1, 2]);
    expect(theory.kind).toBe('spectrum');
    expect(theory).toEqual(probeTheory({ ...params, waves: 'gerstner' }, 3, 4, [0, 1, 2]));
  });
});

describe('the probe’s theory for the seed’s swell', () => {
  const params = { ...defaultParams(), swellFrequency: 0.2, swellAmplitude: 1 };
  const times = Array.from({ length: 1801 }, (_, i) => 10 + i / 60);

  it('is the swell’s formula at the probe’s point and times, with 2π/ω (ω = √(g k)) beside it', () => {
    const theory = probeTheory(params, 13.7, -4.2, times);
    expect(theory.kind).toBe('swell');
    if (theory.kind !== 'swell') return;
    expect(theory.swellPeriod).toBeCloseTo((2 * Math.PI) / Math.sqrt(9.81 * 0.2), 9);
    expect(theory.period).toBe(meanUpCrossingPeriod(swellRecord(params, 13.7, -4.2, times)));
    // The first product alone would rise through zero 1.7 times per 2π/ω; the whole swell does so 1.2 to 1.7 times.
    expect(theory.period).toBeGreaterThan(theory.swellPeriod / 1.8);
    expect(theory.period).toBeLessThan(theory.swellPeriod / 1.1);
    expect(theory.height).toBeGreaterThan(0.5);
    expect(theory.height).toBeLessThanOrEqual(2 * 1.45);
  });

  it('a point does not rise and fall once every 2π/ω: over an hour Tz is 0.73 of it (control for the claim above)', () => {
    const hour = Array.from({ length: 36_000 }, (_, i) => i / 10);
    const theory = probeTheory(params, 13.7, -4.2, hour);
    expect(theory.kind === 'swell' && theory.period / theory.swellPeriod).toBeCloseTo(0.736, 2);
  });
});
