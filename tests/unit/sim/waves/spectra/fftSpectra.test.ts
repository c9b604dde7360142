import { describe, expect, it } from 'vitest';
import {
  angularFrequency,
  GRAVITY,
  groupVelocity,
  quantiseFrequency,
  timeInPeriod,
  waveNumber,
} from '../../../../../src/sim/waves/dispersion';
import {
  cos2sNormalisation,
  cos2sSpreading,
  hasselmannSpreading,
  hasselmannSpreadingExponent,
  logGamma,
} from '../../../../../src/sim/waves/spectra/directionalSpreading';
import { jonswap, jonswapM0Approx, jonswapShape, jonswapWithShape } from '../../../../../src/sim/waves/spectra/jonswap';
import {
  piersonMoskowitz,
  piersonMoskowitzM0,
  piersonMoskowitzPeak,
  windAt19_5,
} from '../../../../../src/sim/waves/spectra/piersonMoskowitz';
import { phillips, phillipsM0, phillipsPeak } from '../../../../../src/sim/waves/spectra/phillips';
import { DEFAULT_SEA_STATE, windVector, type SeaState } from '../../../../../src/sim/waves/spectra/seaState';
import { directionalSpectrum, frequencySpectrum } from '../../../../../src/sim/waves/spectra/waveSpectrum';

/** ∫f over [a, b] by composite Simpson with n (even) intervals. */
function simpson(f: (x: number) => number, a: number, b: number, n = 20000): number {
  const h = (b - a) / n;
  let s = f(a) + f(b);
  for (let i = 1; i < n; i++) s += f(a + i * h) * (i % 2 ? 4 : 2);
  return (s * h) / 3;
}

/** Where f is largest on a fine grid of [a, b]. */
function argmax(f: (x: number) => number, a: number, b: number, n = 200000): number {
  let best = a;
  let value = -Infinity;
  for (let i = 0; i <= n; i++) {
    const x = a + ((b - a) * i) / n;
    const y = f(x);
    if (y > value) [best, value] = [x, y];
  }
  return best;
}

describe('dispersion ω² = g k tanh(k h)', () => {
  it('deep water: a 10 s wave is 156 m long and travels at 15.6 m/s (λ = g T²/2π)', () => {
    const k = waveNumber((2 * Math.PI) / 10);
    expect((2 * Math.PI) / k).toBeCloseTo(156.13, 1);
    expect(angularFrequency(k) / k).toBeCloseTo(15.61, 1);
    expect(groupVelocity(k)).toBeCloseTo(15.61 / 2, 1);
  });

  it('finite depth: a 10 s wave in 10 m of water is 92.3 m long (CEM (USACE 2002) II-1 table)', () => {
    const k = waveNumber((2 * Math.PI) / 10, 10);
    // 92.37 with g = 9.81 (tables use g = 9.80665): within 0.1 %
    expect(Math.abs((2 * Math.PI) / k / 92.3 - 1)).toBeLessThan(1e-3);
    // shallow limit ω → k √(g h), deep limit √(g k)
    expect(angularFrequency(1e-4, 5) / (1e-4 * Math.sqrt(GRAVITY * 5))).toBeCloseTo(1, 6);
    expect(angularFrequency(2, 50)).toBeCloseTo(Math.sqrt(GRAVITY * 2), 12);
    // the deep formula would be wrong here: negative control of the depth term
    expect(Math.abs(Math.sqrt(GRAVITY * k) - (2 * Math.PI) / 10)).toBeGreaterThan(0.05);
  });

  it('group velocity is dω/dk (central difference)', () => {
    for (const [k, h] of [
      [0.05, 10],
      [0.3, 4],
      [1, Infinity],
      [0.02, 200],
    ]) {
      const e = 1e-6 * k;
      const numeric = (angularFrequency(k + e, h) - angularFrequency(k - e, h)) / (2 * e);
      expect(groupVelocity(k, h)).toBeCloseTo(numeric, 6);
    }
  });

  it('quantised dispersion repeats every T and keeps float32 time exact at t = 10⁶ s', () => {
    const T = 1000;
    const omega = quantiseFrequency(angularFrequency(0.7), T);
    expect(Math.abs(omega - angularFrequency(0.7))).toBeLessThan((2 * Math.PI) / T);
    const f = Math.fround;
    const wrap = (a: number) => Math.abs(Math.atan2(Math.sin(a), Math.cos(a)));
    let gpuError = 0;
    let naiveError = 0;
    let unquantisedError = 0;
    for (let i = 0; i < 20; i++) {
      const t = 1e6 + i * 0.137;
      const exact = omega * t;
      // what the GPU does: float32 τ = t mod T (reduced in float64 on the CPU), float32 ω, float32 product
      gpuError = Math.max(gpuError, wrap(f(f(omega) * f(timeInPeriod(t, T))) - exact));
      // negative control: float32 t and ω t at 10⁶ s (ω t ≈ 2.6·10⁶ rad has a float32 spacing of 0.25 rad)
      naiveError = Math.max(naiveError, wrap(f(f(omega) * f(t)) - exact));
      // and without quantisation t mod T would not be the same sea
      unquantisedError = Math.max(unquantisedError, wrap(angularFrequency(0.7) * t - angularFrequency(0.7) * timeInPeriod(t, T)));
    }
    expect(gpuError).toBeLessThan(2e-3);
    expect(naiveError).toBeGreaterThan(0.05);
    expect(unquantisedError).toBeGreaterThan(0.01);
  });
});

describe('Pierson–Moskowitz', { timeout: 60_000 }, () => {
  for (const u of [5, 10, 20]) {
    it(`peaks at ωp = 0.877 g/U19.5 and integrates to its closed-form m₀ at U10 = ${u} m/s`, () => {
      const wp = piersonMoskowitzPeak(u);
      expect(wp / (GRAVITY / windAt19_5(u))).toBeCloseTo(0.877, 3);
      expect(argmax((w) => piersonMoskowitz(w, u), 0.2 * wp, 5 * wp) / wp).toBeCloseTo(1, 3);
      const m0 = simpson((w) => piersonMoskowitz(w, u), 0.05 * wp, 60 * wp, 40000);
      expect(m0 / piersonMoskowitzM0(u)).toBeCloseTo(1, 4);
      // Hs = 4√m₀ = 0.21 U19.5²/g (Pierson & Moskowitz 1964)
      expect((4 * Math.sqrt(m0)) / ((0.21 * windAt19_5(u) ** 2) / GRAVITY)).toBeCloseTo(0.996, 2);
    });
  }
  it('negative control: a spectrum with β = 1 does not peak at 0.877 g/U19.5', () => {
    const u = 10;
    const w0 = GRAVITY / windAt19_5(u);
    const wrong = (w: number) => 8.1e-3 * GRAVITY ** 2 * w ** -5 * Math.exp(-((w0 / w) ** 4));
    expect(Math.abs(argmax(wrong, 0.1, 5) / piersonMoskowitzPeak(u) - 1)).toBeGreaterThan(0.05);
  });
});

describe('JONSWAP (Hasselmann et al. 1973)', { timeout: 60_000 }, () => {
  it('α and ωp follow the fetch laws and stop at the fully developed sea', () => {
    const s = jonswapShape(10, 20_000);
    expect(s.alpha).toBeCloseTo(0.076 * ((10 * 10) / (20_000 * GRAVITY)) ** 0.22, 12);
    expect(s.peak).toBeCloseTo(22 * (GRAVITY ** 2 / (10 * 20_000)) ** (1 / 3), 12);
    const developed = jonswapShape(10, 1e8);
    expect(developed.peak).toBeCloseTo(piersonMoskowitzPeak(10), 12);
    // at the cap α is Pierson–Moskowitz's 8.1e-3 to within the two fits' disagreement
    expect(developed.alpha).toBeGreaterThan(0.006);
    expect(developed.alpha).toBeLessThan(0.011);
  });
  for (const [u, fetch] of [
    [10, 20_000],
    [20, 20_000],
    [15, 100_000],
  ]) {
    // The closed form for γ = 1, the DNV approximation for γ = 3.3.
    it(`peaks at ωp and m₀ matches its closed form and DNV's, U = ${u}, F = ${fetch / 1000} km`, () => {
      const { alpha, peak } = jonswapShape(u, fetch);
      expect(argmax((w) => jonswap(w, u, fetch), 0.3 * peak, 4 * peak) / peak).toBeCloseTo(1, 3);
      const m1 = simpson((w) => jonswapWithShape(w, alpha, peak, 1), 0.05 * peak, 60 * peak, 40000);
      expect(m1 / ((alpha * GRAVITY ** 2) / (5 * peak ** 4))).toBeCloseTo(1, 4);
      const m33 = simpson((w) => jonswapWithShape(w, alpha, peak), 0.05 * peak, 60 * peak, 40000);
      // measured: 1.0026; DNV quotes a few per cent
      expect(Math.abs(m33 / jonswapM0Approx(alpha, peak) - 1)).toBeLessThan(0.01);
    });
  }
  it('negative control: the peak enhancement γ really adds energy (γ = 3.3 vs γ = 1 differ by > 40 %)', () => {
    const { alpha, peak } = jonswapShape(10, 20_000);
    const m1 = simpson((w) => jonswapWithShape(w, alpha, peak, 1), 0.05 * peak, 60 * peak);
    const m33 = simpson((w) => jonswapWithShape(w, alpha, peak), 0.05 * peak, 60 * peak);
    expect(m33 / m1).toBeGreaterThan(1.4);
  });
});

describe('Phillips (Tessendorf 2001)', { timeout: 60_000 }, () => {
  it('peaks at (4/5)^¼ g/U and integrates to α U⁴/(4 g²)', () => {
    for (const u of [4, 12]) {
      const wp = phillipsPeak(u);
      expect(argmax((w) => phillips(w, u), 0.2 * wp, 5 * wp) / wp).toBeCloseTo(1, 3);
      expect(simpson((w) => phillips(w, u), 0.05 * wp, 60 * wp, 40000) / phillipsM0(u)).toBeCloseTo(1, 4);
    }
  });
});

describe('cos-2s directional spreading', () => {
  it('log Γ matches known values', () => {
    expect(Math.exp(logGamma(5))).toBeCloseTo(24, 10);
    expect(Math.exp(logGamma(0.5))).toBeCloseTo(Math.sqrt(Math.PI), 12);
    expect(Math.exp(logGamma(10.5))).toBeCloseTo(1133278.3889487856, 4);
  });
  for (const s of [0.5, 1, 2.5, 8, 30]) {
    it(`integrates to 1 over θ for s = ${s}, peaks along the wind`, () => {
      expect(simpson((t) => cos2sSpreading(t, s), -Math.PI, Math.PI)).toBeCloseTo(1, 8);
      expect(cos2sSpreading(0, s)).toBeGreaterThan(cos2sSpreading(0.3, s));
      expect(cos2sSpreading(Math.PI, s)).toBeCloseTo(0, 12);
    });
  }
  it('negative control: without N(s) the integral is not 1', () => {
    const raw = simpson((t) => cos2sSpreading(t, 8) / cos2sNormalisation(8), -Math.PI, Math.PI);
    expect(Math.abs(raw - 1)).toBeGreaterThan(0.1);
  });
});

describe('Hasselmann et al. (1980) directional spreading', () => {
  // A fully developed sea at 15 m/s: ωp from Pierson–Moskowitz.
  const U = 15;
  const wp = piersonMoskowitzPeak(U);
  for (const r of [0.6, 1, 1.05, 1.5, 3]) {
    it(`integrates to 1 over θ and peaks on the wind at ω = ${r} ωp`, () => {
      const d = (t: number) => hasselmannSpreading(t, r * wp, wp, U);
      expect(simpson(d, -Math.PI, Math.PI)).toBeCloseTo(1, 8);
      expect(Math.abs(argmax(d, -Math.PI, Math.PI))).toBeLessThan(1e-4);
      expect(d(0)).toBeGreaterThan(d(0.5));
    });
  }
  it('is narrowest just above the peak (s ≈ 9, published), wider for longer and shorter waves', () => {
    const s = (r: number) => hasselmannSpreadingExponent(r * wp, wp, U);
    expect(s(1)).toBeCloseTo(6.97, 10);
    expect(s(1.05)).toBeGreaterThan(8);
    expect(s(1.05)).toBeLessThan(10);
    expect(s(0.5)).toBeLessThan(s(1));
    expect(s(3)).toBeLessThan(s(1.05));
    // The two branches nearly meet at 1.05 ωp (measured: 8.50 from the lower, 8.92 from the upper, this sea).
    expect(Math.abs(6.97 * 1.05 ** 4.06 - s(1.05))).toBeLessThan(1);
  });
  // The peak's exponent; Hasselmann's spreads them (measured 24× more at 90° for 3 ωp).
  it('negative control: one exponent for all frequencies keeps short waves near the wind', () => {
    const blind = (t: number) => cos2sSpreading(t, hasselmannSpreadingExponent(wp, wp, U));
    const short = (t: number) => hasselmannSpreading(t, 3 * wp, wp, U);
    expect(short(Math.PI / 2)).toBeGreaterThan(10 * blind(Math.PI / 2));
  });
});

describe('the spectral sea with Hasselmann spreading', () => {
  /** ∫∫F dkx dkz in polar coordinates (k dk dθ), k up to 60 kp: the sea's variance. */
  function polarVariance(sea: SeaState): { total: number; crossWind: number } {
    const spectrum = frequencySpectrum(sea);
    const F = directionalSpectrum(sea, spectrum);
    const kp = waveNumber(spectrum.peak, sea.depth);
    const [wx, wz] = windVector(sea.windDirection);
    const wind = Math.atan2(wz, wx);
    const ring = (k: number, theta: number) => F(k * Math.cos(wind + theta), k * Math.sin(wind + theta)) * k;
    const total = simpson((k) => simpson((t) => ring(k, t), -Math.PI, Math.PI, 160), 1e-6, 60 * kp, 1200);
    // Energy of waves 3–6 kp long travelling more than 60° off the wind.
    const crossWind = simpson((k) => 2 * simpson((t) => ring(k, t), Math.PI / 3, Math.PI, 80), 3 * kp, 6 * kp, 100);
    return { total, crossWind };
  }
  // The spreading only moves energy between directions (planted fault: cos-2s s = 8 is the other sea).
  it('keeps m₀ and sends more short-wave energy across the wind than cos-2s', () => {
    const base: SeaState = { ...DEFAULT_SEA_STATE, windSpeed: 15 };
    const cos2s = polarVariance(base);
    const hasselmann = polarVariance({ ...base, spreadingModel: 'hasselmann' });
    const m0 = piersonMoskowitzM0(15);
    expect(Math.abs(cos2s.total / m0 - 1)).toBeLessThan(0.01);
    expect(Math.abs(hasselmann.total / m0 - 1)).toBeLessThan(0.01);
    console.log(
      `[oceano] m₀ ${m0.toFixed(4)} m²: cos-2s ${cos2s.total.toFixed(4)}, Hasselmann ${hasselmann.total.toFixed(4)}; short waves > 60° off the wind: ${cos2s.crossWind.toExponential(2)} against ${hasselmann.crossWind.toExponential(2)} m²`,
    );
    // Measured: both within 0.04 % of m₀; 6.6× the cross-wind energy with Hasselmann.
    expect(hasselmann.crossWind).toBeGreaterThan(4 * cos2s.crossWind);
  });
});
