import { describe, expect, it } from 'vitest';
import { cos2sSpreading } from '../../../../src/sim/waves/spectra/directionalSpreading';
import { GerstnerLiveModel } from '../../../../src/sim/waves/gerstner/gerstnerLiveModel';
import { gerstnerSea } from '../../../../src/sim/waves/gerstner/gerstnerSpectrum';
import { GerstnerWaveModel } from '../../../../src/sim/waves/gerstner/gerstnerWaves';
import { defaultParams } from '../../../../src/sim/params/params';
import { jonswapHs, measurePhysics, physicsSteps, piersonMoskowitzHs, type MeasuredSea } from '../../../../src/sim/physics/physicsReport';
import { piersonMoskowitz } from '../../../../src/sim/waves/spectra/piersonMoskowitz';
import { seaStateFromParams } from '../../../../src/sim/waves/spectra/seaState';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';

const SLOW = 120_000;

function gerstnerReport(windSpeed: number) {
  const params = { ...defaultParams(), waves: 'gerstner' as const, windSpeed, spectrum: 'pierson-moskowitz' as const };
  const model = new GerstnerLiveModel(params);
  return measurePhysics(
    {
      name: 'gerstner',
      height: (x, z, t) => model.height(x, z, t),
      sea: seaStateFromParams(params),
      slopeVariance: () => model.slopeVariance(),
      windSpeed,
      seaRoughness: true,
    },
    100,
  );
}

describe("the physics panel's report on the Gerstner sea (PM, seed 1, 32 waves, Q = 0.6, from t = 100 s)", () => {
  it.each([5, 10, 15])(
    'U₁₀ = %s m/s: dispersion, ωp, Tp and Hs within tolerance of theory',
    (u) => {
      const r = gerstnerReport(u);
      // Measured (fit; ωp/theory; Hs/4√m₀; Hs/0.21U²/g): U=5: 1.039, 0.910, 0.994, 0.990;
      // U=10: 1.055, 1.069, 0.994, 0.990; U=15: 0.997, 1.069, 0.993, 0.989. The peak is the weak
      // figure: 32 waves put only a few near PM's flat top (see physicsEstimators.test.ts).
      expect(Math.abs(r.dispersion.fitRatio - 1)).toBeLessThan(0.08);
      expect(Math.abs(r.peak.measured / r.peak.theory! - 1)).toBeLessThan(0.12);
      expect(Math.abs(r.peakPeriod.measured / r.peakPeriod.theory! - 1)).toBeLessThan(0.12);
      // 16 points × 512 samples (64 Tp each, not one point's 1024 Tp): the beats of 32 waves leave
      // 2.3–2.5 % in 4σ(η) at U = 5, 10, 15.
      expect(Math.abs(r.hs.measured / r.hs.spectral! - 1)).toBeLessThan(0.03);
      expect(Math.abs(r.hs.measured / r.hs.empirical! - 1)).toBeLessThan(0.03);
      expect(r.spectrum.theory).not.toBeNull();
      expect(r.citations.map((c) => c.source).join(' ')).toMatch(/Pierson & Moskowitz 1964/);
    },
    SLOW,
  );

  it(
    'negative control: the same sea with ω² = g k (1 + k²) fails the dispersion fit',
    () => {
      const params = { ...defaultParams(), waves: 'gerstner' as const, windSpeed: 3, spectrum: 'pierson-moskowitz' as const };
      const sea = seaStateFromParams(params);
      const wrong = (k: number) => Math.sqrt(9.81 * k * (1 + k * k));
      const model = new GerstnerWaveModel(
        gerstnerSea({
          count: 32,
          seed: 1,
          spectrum: (w) => piersonMoskowitz(w, 3),
          spreading: (theta) => cos2sSpreading(theta, sea.spreading),
          windDirection: 0,
          steepness: 0.6,
          dispersion: wrong,
        }),
      );
      const r = measurePhysics(
        {
          name: 'gerstner',
          height: (x, z, t) => model.sample(x, z, t).height,
          sea,
          slopeVariance: () => 0,
          windSpeed: 3,
          seaRoughness: true,
        },
        100,
      );
      // At U = 3 m/s the waves are short (k ≈ 1 rad/m), where the slip doubles ω² .
      expect(r.dispersion.fitRatio).toBeGreaterThan(1.2);
    },
    SLOW,
  );
});

describe('empirical Hs laws, by hand', () => {
  it('PM: 0.21 U₁₉.₅²/g; JONSWAP: 1.6·10⁻³ U₁₀ √(F/g), capped at PM', () => {
    // U₁₀ = 10: U₁₉.₅ = 10.26, 0.21 · 105.27 / 9.81 = 2.2534 m.
    expect(piersonMoskowitzHs(10)).toBeCloseTo(2.2534, 3);
    // U₁₀ = 10, F = 100 km: 1.6e-3 · 10 · √(1e5 / 9.81) = 1.6154 m.
    expect(jonswapHs(10, 100e3)).toBeCloseTo(1.6154, 3);
    // A fetch of 10 000 km would exceed the fully developed sea: capped.
    expect(jonswapHs(10, 1e7)).toBeCloseTo(piersonMoskowitzHs(10), 9);
  });
});

describe('the seed model', () => {
  it(
    'is measured without a spectrum theory and says its ripples follow no dispersion law',
    () => {
      const params = defaultParams();
      const model = new SeedWaveModel(params);
      const r = measurePhysics(
        {
          name: 'seed',
          height: (x, z, t) => model.height(x, z, t),
          sea: { swellWavenumber: params.swellFrequency },
          slopeVariance: (t) => model.slopeVariance(t),
          windSpeed: params.windSpeed,
          seaRoughness: true,
        },
        10,
      );
      expect(r.spectrum.theory).toBeNull();
      expect(r.hs.spectral).toBeNull();
      expect(r.notes.join(' ')).toMatch(/follow no dispersion law/);
      // Its slopes and the roughness its glint adds make Cox & Munk's σ² for the app's wind,
      // 0.003 + 5.12·10⁻³ · 10.201 = 0.05523 at U₁₀ = 10 m/s (U₁₂.₅ by the log profile).
      expect(r.slopes.coxMunk).toBeCloseTo(0.05523, 5);
      expect(r.slopes.wind).toBeCloseTo(10.201, 3);
      expect(r.slopes.resolved).toBeCloseTo(model.slopeVariance(10), 12);
      expect(r.slopes.total).toBeCloseTo(0.05523, 5);
    },
    SLOW,
  );
});

describe('the slopes row: resolved + roughness against Cox & Munk', () => {
  /** The Gerstner sea at this wind, reporting the slopes given: the row alone is under test. */
  const flat = (slopeVariance: number, windSpeed: number) => {
    const params = { ...defaultParams(), waves: 'gerstner' as const, windSpeed };
    const model = new GerstnerLiveModel(params);
    return measurePhysics(
      {
        name: 'gerstner',
        height: (x, z, t) => model.height(x, z, t),
        sea: seaStateFromParams(params),
        slopeVariance: () => slopeVariance,
        windSpeed,
        seaRoughness: true,
      },
      100,
    );
  };

  // Control: slopes steeper than Cox & Munk’s are shown above it, with a note.
  it(
    'the roughness makes up Cox & Munk’s σ² at 5 and 15 m/s (0.02911, 0.08134)',
    () => {
      for (const [u, sigma2] of [
        [5, 0.02911],
        [15, 0.08134],
      ]) {
        const r = flat(0.01, u);
        expect(r.slopes.coxMunk).toBeCloseTo(sigma2, 4);
        expect(r.slopes.roughness).toBeCloseTo(r.slopes.coxMunk - 0.01, 12);
        expect(r.slopes.total).toBeCloseTo(r.slopes.coxMunk, 12);
      }
      const steep = flat(0.13, 20);
      expect(steep.slopes.total).toBeGreaterThan(steep.slopes.coxMunk + 0.004);
      expect(steep.notes.join(' ')).toMatch(/exceed Cox & Munk/);
    },
    SLOW,
  );
});

// The panel spreads a measurement over tasks so the page's other figures keep drawing.
describe('the measurement as steps', () => {
  const params = { ...defaultParams(), waves: 'gerstner' as const, windSpeed: 10, spectrum: 'pierson-moskowitz' as const };
  const model = new GerstnerLiveModel(params);
  const times: number[] = [];
  const sea = (record: boolean): MeasuredSea => ({
    name: 'gerstner',
    height: (x, z, t) => (record && times.push(t), model.height(x, z, t)),
    sea: seaStateFromParams(params),
    slopeVariance: () => model.slopeVariance(),
    windSpeed: 10,
    seaRoughness: true,
  });

  it(
    "gives measurePhysics's report, one simulated time a step",
    () => {
      const steps = physicsSteps(sea(true), 100);
      const timesPerStep: number[] = [];
      let step = steps.next();
      while (!step.done) {
        timesPerStep.push(new Set(times.splice(0)).size);
        step = steps.next();
      }
      // 16 snapshots for the dispersion, then 512 times of the 16 probe points.
      expect(timesPerStep.length).toBe(16 + 512);
      expect(timesPerStep.every((n) => n === 1)).toBe(true);
      expect(step.value).toEqual(measurePhysics(sea(false), 100));
      // Control: the report from another start time differs, so the equality above is not vacuous.
      expect(measurePhysics(sea(false), 130).hs.measured).not.toBe(step.value.hs.measured);
    },
    SLOW,
  );
});
