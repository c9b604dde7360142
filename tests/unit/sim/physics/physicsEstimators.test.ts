import { describe, expect, it } from 'vitest';

/** The heavier estimator tests take 1–3 s alone; the shared 2-core machine can triple that. */
const SLOW = 30_000;
import {
  estimateDispersion,
  fitDispersion,
  frequencySpectrum,
  heightSeries,
  heightSeriesAt,
  peakPeriod,
  significantWaveHeight,
  spectralMoment0,
  spectralPeak,
  type HeightSampler,
} from '../../../../src/sim/physics/physicsEstimators';
import { gerstnerSea, linearDispersion, type Dispersion } from '../../../../src/sim/waves/gerstner/gerstnerSpectrum';
import { GerstnerWaveModel } from '../../../../src/sim/waves/gerstner/gerstnerWaves';
import { seededRandom } from '../../../../src/sim/noise/integerHash';
import { G, cosineSquared, jonswap, piersonMoskowitz } from '../../../support/testSeas';

const TWO_PI = 2 * Math.PI;
const deep: Dispersion = (k) => Math.sqrt(G * k);
/** The slip found in a well-known WebGL ocean (k*k/KM*KM, i.e. k²): ω² = g k (1 + k²). */
const wrong: Dispersion = (k) => Math.sqrt(G * k * (1 + k * k));

interface Sea {
  sampler: HeightSampler;
  /** Variance the components carry, m². */
  m0: number;
}

/**
 * A linear random-phase sea built the way a spectral (FFT) ocean builds one: wavenumbers
 * and amplitudes are fixed from the spectrum through the true deep-water relation (so the
 * sea has the spectrum's wavelengths), then each component oscillates at the ω that the
 * dispersion under test gives its k. With the true relation the frequency spectrum is S(ω);
 * with a wrong one, the same wavelengths run at wrong frequencies, as in the buggy ocean.
 * 128 components, equal Δω over [0.3, 6] ωp (PM keeps all but 0.1 % of m₀ there), random
 * place in each bin, cos² directions about +x, seeded phases.
 */
function linearSea(spectrum: (w: number) => number, peak: number, seed: number, dispersion: Dispersion, amplitudeSlip = 1): Sea {
  const random = seededRandom(seed);
  const count = 128;
  const lo = 0.3 * peak;
  const dw = (5.7 * peak) / count;
  const kx: number[] = [];
  const kz: number[] = [];
  const omega: number[] = [];
  const amp: number[] = [];
  const phase: number[] = [];
  let m0 = 0;
  for (let i = 0; i < count; i++) {
    const w = lo + (i + random()) * dw;
    // cos² directions by rejection: θ uniform on (−π/2, π/2), kept with probability cos² θ.
    let theta = 0;
    do theta = (random() - 0.5) * Math.PI;
    while (random() > Math.cos(theta) ** 2);
    const k = (w * w) / G;
    const a = Math.sqrt(2 * spectrum(w) * dw) * amplitudeSlip;
    kx.push(k * Math.cos(theta));
    kz.push(k * Math.sin(theta));
    omega.push(dispersion(k));
    amp.push(a);
    phase.push(TWO_PI * random());
    m0 += (a * a) / 2;
  }
  return {
    m0,
    sampler: (x, z, t) => {
      let h = 0;
      for (let i = 0; i < count; i++) h += amp[i] * Math.cos(kx[i] * x + kz[i] * z - omega[i] * t + phase[i]);
      return h;
    },
  };
}

/** Dispersion measured on a patch four peak wavelengths wide, snapshots Tp / 16 apart. */
function measuredDispersion(sampler: HeightSampler, peak: number, resolution = 32, snapshots = 16) {
  const lambda = (TWO_PI * G) / (peak * peak);
  return estimateDispersion(sampler, { size: 4 * lambda, resolution, startTime: 100, timeStep: TWO_PI / peak / 16, snapshots, modes: 24 });
}

/** ∫ S dω by the trapezoid rule on a fine log grid. */
function integrate(spectrum: (w: number) => number): number {
  let sum = 0;
  const n = 20000;
  for (let i = 0; i < n; i++) {
    const a = 0.01 * Math.pow(4000, i / n);
    const b = 0.01 * Math.pow(4000, (i + 1) / n);
    sum += 0.5 * (spectrum(a) + spectrum(b)) * (b - a);
  }
  return sum;
}

const seas = {
  'PM, U = 3 m/s': piersonMoskowitz(3),
  'PM, U = 10 m/s': piersonMoskowitz(10),
  'JONSWAP, U = 10 m/s, F = 100 km': jonswap(10, 100e3),
  'JONSWAP, U = 6 m/s, F = 5 km': jonswap(6, 5e3),
};

describe('Dispersion estimator: ω(k) from the phases of spatial Fourier modes', () => {
  it.each(Object.entries(seas))(
    'recovers √(g k) within 3 %% on a synthesised sea (%s, seed 1)',
    (_, sea) => {
      const synth = linearSea(sea.spectrum, sea.peak, 1, deep);
      const fit = fitDispersion(measuredDispersion(synth.sampler, sea.peak), deep);
      // Measured over these four seas: |ratio − 1| ≤ 1.5 %, rms ≤ 11.4 % (a 32 × 32 patch: the
      // centroid k of a mode shared by neighbouring components scatters by a fraction of a bin).
      // The wrong-dispersion control below gives ratio 1.75, rms 0.97.
      expect(Math.abs(fit.ratio - 1)).toBeLessThan(0.03);
      expect(fit.rmsRelativeError).toBeLessThan(0.15);
    },
    SLOW,
  );

  it(
    'negative control: a sea whose waves obey ω² = g k (1 + k²) fails the fit (PM, U = 3 m/s, λp ≈ 8 m)',
    () => {
      const sea = seas['PM, U = 3 m/s'];
      const synth = linearSea(sea.spectrum, sea.peak, 1, wrong);
      const fit = fitDispersion(measuredDispersion(synth.sampler, sea.peak), deep);
      // At kp = 0.8 rad/m the slip runs waves √1.64 = 1.28 times too fast, shorter ones more.
      // Measured ratio 1.75.
      expect(fit.ratio).toBeGreaterThan(1.15);
      expect(fit.rmsRelativeError).toBeGreaterThan(0.15);
    },
    SLOW,
  );

  it(
    'finds finite-depth dispersion √(g k tanh k h) and tells it from deep water (h = 3 m, PM 10 m/s)',
    () => {
      const sea = seas['PM, U = 10 m/s'];
      const shallow = linearDispersion(3);
      const random = seededRandom(4);
      // Components fixed in k this time (the shallow k of each ω), running at the shallow ω.
      const comps = Array.from({ length: 128 }, (_, i) => {
        const w = (0.5 + (i + random()) * (3 / 128)) * sea.peak;
        let k = (w * w) / G;
        for (let j = 0; j < 60; j++) k = (w * w) / (G * Math.tanh(k * 3));
        return {
          k,
          w: shallow(k),
          a: Math.sqrt(2 * sea.spectrum(w) * ((3 * sea.peak) / 128)),
          theta: (random() - 0.5) * 0.6,
          phase: TWO_PI * random(),
        };
      });
      const sampler: HeightSampler = (x, z, t) => {
        let h = 0;
        for (const c of comps) h += c.a * Math.cos(c.k * (Math.cos(c.theta) * x + Math.sin(c.theta) * z) - c.w * t + c.phase);
        return h;
      };
      const points = estimateDispersion(sampler, { size: 200, resolution: 32, startTime: 0, timeStep: 0.5, snapshots: 16, modes: 24 });
      const right = fitDispersion(points, shallow);
      const deepFit = fitDispersion(points, deep);
      // Measured 0.8 %; deep-water theory gives 0.72.
      expect(Math.abs(right.ratio - 1)).toBeLessThan(0.03);
      // Shallow water slows the peak waves (kh ≈ 0.5) by a third: deep-water theory is far off.
      expect(deepFit.ratio).toBeLessThan(0.8);
    },
    SLOW,
  );
});

describe('Dispersion of the Gerstner sea, measured through its CPU twin (sample at world points)', () => {
  const pm = piersonMoskowitz(3);
  const options = { count: 24, seed: 3, spectrum: pm.spectrum, spreading: cosineSquared, windDirection: 0, steepness: 0.6 };

  it(
    'follows √(g k) within 6 % (24 waves, PM 3 m/s, Q = 0.6)',
    () => {
      const model = new GerstnerWaveModel(gerstnerSea(options));
      const fit = fitDispersion(
        measuredDispersion((x, z, t) => model.sample(x, z, t).height, pm.peak),
        deep,
      );
      // Measured ratio 1.048: a Gerstner crest's harmonics at 2k run at 2ω(k), faster than
      // free waves of wavenumber 2k (√2 ω(k)), and pull the weighted ratio up a little.
      expect(Math.abs(fit.ratio - 1)).toBeLessThan(0.06);
    },
    SLOW,
  );

  it(
    'negative control: the same sea built with ω² = g k (1 + k²) is caught',
    () => {
      const model = new GerstnerWaveModel(gerstnerSea({ ...options, dispersion: wrong }));
      const fit = fitDispersion(
        measuredDispersion((x, z, t) => model.sample(x, z, t).height, pm.peak),
        deep,
      );
      // Measured 1.33.
      expect(fit.ratio).toBeGreaterThan(1.2);
    },
    SLOW,
  );
});

describe("Frequency spectrum, peak period and Hs of one point's height series", () => {
  /** 8192 samples Tp / 16 apart (about 64 minutes at U = 10 m/s), Welch segments of 512. */
  function measure(sampler: HeightSampler, peak: number) {
    const dt = TWO_PI / peak / 8;
    const series = heightSeries(sampler, 13.7, -4.2, 50, dt, 8192);
    const spectrum = frequencySpectrum(series, dt, 512);
    return { peak: spectralPeak(spectrum), hs: significantWaveHeight(series), m0: spectralMoment0(spectrum) };
  }

  it.each(Object.entries(seas))(
    'recover ωp within 8 %% and Hs within 3 %% of theory (%s, seeds 1–2)',
    (_, sea) => {
      const theoryHs = 4 * Math.sqrt(integrate(sea.spectrum));
      for (let seed = 1; seed <= 2; seed++) {
        const m = measure(linearSea(sea.spectrum, sea.peak, seed, deep).sampler, sea.peak);
        // Measured worst: ωp 7.7 %, Hs 1.6 %. The peak is the weak one: 128 components put
        // only a few near PM's flat top, so where the sea's own maximum sits scatters by
        // about a component spacing (4.5 % of ωp) before any estimation error.
        expect(Math.abs(m.peak / sea.peak - 1)).toBeLessThan(0.08);
        expect(Math.abs(m.hs / theoryHs - 1)).toBeLessThan(0.03);
        // Parseval: the spectrum's m₀ is the series' variance (Hann/Welch normalisation).
        // Measured within 0.3 %.
        expect(Math.abs(Math.sqrt(m.m0) / (m.hs / 4) - 1)).toBeLessThan(0.01);
      }
    },
    SLOW,
  );

  it(
    'PM: Hs against the empirical 0.21 U₁₉.₅²/g and Tp against 2π/ωp',
    () => {
      const pm = piersonMoskowitz(10);
      const m = measure(linearSea(pm.spectrum, pm.peak, 1, deep).sampler, pm.peak);
      // Measured Hs −0.3 %, Tp +6.6 %.
      expect(Math.abs(m.hs / pm.hs - 1)).toBeLessThan(0.03);
      expect(Math.abs(peakPeriod(m.peak) / peakPeriod(pm.peak) - 1)).toBeLessThan(0.08);
    },
    SLOW,
  );

  it(
    'negative control: wavelengths from the spectrum run with ω² = g k (1 + k²) move the peak (PM 3 m/s)',
    () => {
      const pm = seas['PM, U = 3 m/s'];
      const m = measure(linearSea(pm.spectrum, pm.peak, 1, wrong).sampler, pm.peak);
      // Measured 1.55.
      expect(m.peak / pm.peak).toBeGreaterThan(1.15);
    },
    SLOW,
  );

  it(
    'negative control: amplitudes √(S Δω) instead of √(2 S Δω) (a common slip) fail the Hs check',
    () => {
      const pm = seas['PM, U = 10 m/s'];
      const m = measure(linearSea(pm.spectrum, pm.peak, 1, deep, Math.SQRT1_2).sampler, pm.peak);
      // Measured −29 % (1 − 1/√2).
      expect(Math.abs(m.hs / (4 * Math.sqrt(integrate(pm.spectrum))) - 1)).toBeGreaterThan(0.2);
    },
    SLOW,
  );

  it(
    "the Gerstner sea's Hs at a point matches 4√(Σ Aᵢ²/2) of its waves (32 waves, JONSWAP 10 m/s, 100 km)",
    () => {
      const sea = seas['JONSWAP, U = 10 m/s, F = 100 km'];
      const waves = gerstnerSea({
        count: 32,
        seed: 5,
        spectrum: sea.spectrum,
        spreading: cosineSquared,
        windDirection: 0.4,
        steepness: 0.5,
      });
      const model = new GerstnerWaveModel(waves);
      const m = measure((x, z, t) => model.sample(x, z, t).height, sea.peak);
      const hs = 4 * Math.sqrt(waves.reduce((s, w) => s + (w.amplitude * w.amplitude) / 2, 0));
      // Measured Hs +0.01 %, ωp +2.8 %.
      expect(Math.abs(m.hs / hs - 1)).toBeLessThan(0.03);
      expect(Math.abs(m.peak / sea.peak - 1)).toBeLessThan(0.08);
    },
    SLOW,
  );
});

describe('Estimator input checks', () => {
  it(
    'reject sizes that are not powers of two and series shorter than a segment',
    () => {
      expect(() => frequencySpectrum(new Float64Array(100), 1, 100)).toThrow(/power of two/);
      expect(() => frequencySpectrum(new Float64Array(100), 1, 128)).toThrow(/shorter/);
      expect(() => estimateDispersion(() => 0, { size: 10, resolution: 48, startTime: 0, timeStep: 1, snapshots: 4 })).toThrow(
        /power of two/,
      );
    },
    SLOW,
  );
});

describe('heightSeriesAt: many points, one pass over time', () => {
  it('gives each point its own series, identical to heightSeries there, with time the outer loop', () => {
    const sampler = (x: number, z: number, t: number) => Math.sin(0.3 * x + 0.7 * t) * Math.cos(0.2 * z);
    const points: [number, number][] = [
      [1, 2],
      [40, -7],
      [-13, 5],
    ];
    const order: number[] = [];
    const many = heightSeriesAt((x, z, t) => (order.push(t), sampler(x, z, t)), points, 5, 0.25, 64);
    points.forEach(([x, z], p) => expect(Array.from(many[p])).toEqual(Array.from(heightSeries(sampler, x, z, 5, 0.25, 64))));
    // A twin that computes a field per new time: 64 changes of time, not 3 × 64.
    let changes = 0;
    order.forEach((t, i) => (changes += i === 0 || t !== order[i - 1] ? 1 : 0));
    expect(changes).toBe(64);
    // Negative control: point by point, the same samples change time 3 × 64 times.
    const byPoint = points.flatMap(() => Array.from({ length: 64 }, (_, i) => 5 + i * 0.25));
    expect(byPoint.filter((t, i) => i === 0 || t !== byPoint[i - 1]).length).toBe(192);
  });
});
