import { describe, expect, it } from 'vitest';
import { BEACH_SHORE_X, OFFSHORE_DEPTH, seaDepth } from '../../../../src/sim/coast/bathymetry';
import type { CoastField, CoastSetting } from '../../../../src/sim/coast/coastField';
import { coastSwellHeight, sampleCoastField } from '../../../../src/sim/coast/coastFieldSampling';
import { buildCoastField } from '../../../../src/sim/coast/coastSwellField';
import { coastSwellAt } from '../../../../src/sim/coast/coastSwellSlope';
import { CoastSurface } from '../../../../src/sim/coast/coastSurface';
import { LINEAR_THEORY } from '../../../../src/sim/coast/coastWaveModel';
import { setPeriod, swellComponents } from '../../../../src/sim/coast/swellSpectrum';
import {
  MCCOWAN_BREAKER_INDEX,
  refractionCoefficient,
  shoalingCoefficient,
  snellAngle,
} from '../../../../src/sim/coast/waveTransformation';
import { defaultParams } from '../../../../src/sim/params/params';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';
import { relativeError } from '../../../support/coastSurface';

/** The beach of the lessons: slope 0.02, a 1.5 m, 10 s swell head-on, its spectrum's phases from seed 1. */
const SETTING: CoastSetting = {
  bathymetry: 'beach',
  beachSlope: 0.02,
  deepDepth: OFFSHORE_DEPTH,
  swellHeight: 1.5,
  swellPeriod: 10,
  swellDirection: 0,
  seed: 1,
};
const build = (setting: Partial<CoastSetting> = {}, model = LINEAR_THEORY): CoastField =>
  buildCoastField({ ...SETTING, ...setting }, 256, model)!;
const FIELD = build();
const SET = setPeriod(swellComponents(SETTING));
const xAtDepth = (depth: number): number => BEACH_SHORE_X - depth / SETTING.beachSlope;
const GAMMA = MCCOWAN_BREAKER_INDEX;

/** The largest |η| at (x, 0) over `sets` set periods, every half second. */
function largestHeight(field: CoastField, x: number, limited: boolean, sets = 3): number {
  let largest = 0;
  for (let t = 0; t < sets * SET; t += 0.5) largest = Math.max(largest, Math.abs(coastSwellHeight(field, x, 0, t, limited)));
  return largest;
}

describe('the swell’s sets break on the envelope: no wave higher than γ h', () => {
  const DEPTHS = [1, 2, 3, 4, 5];

  it('over three set periods |η| stays within γ h / 2 (+1 %) at depths of 1 to 5 m', () => {
    for (const depth of DEPTHS)
      expect(largestHeight(FIELD, xAtDepth(depth), true), `${depth} m`).toBeLessThanOrEqual(1.01 * GAMMA * depth * 0.5);
  });

  it('the same field without the limit (a planted fault) rises above γ h / 2 inside the surf zone (1 and 2 m)', () => {
    for (const depth of [1, 2])
      expect(largestHeight(FIELD, xAtDepth(depth), false), `${depth} m`).toBeGreaterThan(1.01 * GAMMA * depth * 0.5);
  });

  it('between sets smaller waves reach the shallows unbroken: at 2 m the breaking fraction is 0 for a while', () => {
    let unbroken = 0;
    let broken = 0;
    const samples = Math.ceil((3 * SET) / 0.5);
    for (let s = 0; s < samples; s++) {
      const breaking = coastSwellAt(FIELD, xAtDepth(2), 0, s * 0.5).breaking;
      if (breaking === 0) unbroken++;
      if (breaking >= 1) broken++;
    }
    expect(unbroken / samples).toBeGreaterThan(0.05);
    expect(broken / samples).toBeGreaterThan(0.05);
  });
});

/** Σ A_m at depth h by linear theory for the setting's components: a_m Ks(ω_m) Kr(ω_m), head-on or at θ0. */
function theoreticalEnvelope(depth: number): number {
  const theta0 = (SETTING.swellDirection * Math.PI) / 180;
  return swellComponents(SETTING).reduce((sum, c) => {
    const omega = c.angularFrequency;
    const kr = refractionCoefficient(theta0, snellAngle(omega, theta0, depth, OFFSHORE_DEPTH));
    return sum + c.amplitude * shoalingCoefficient(omega, depth, OFFSHORE_DEPTH) * kr;
  }, 0);
}

/** The depth where 2 Σ A_m = γ h, by bisection: the set's biggest wave reaches the breaker limit there. */
function theoreticalOutermostBreaking(): number {
  let shallow = 0.05;
  let deep = OFFSHORE_DEPTH;
  for (let i = 0; i < 60; i++) {
    const mid = 0.5 * (shallow + deep);
    if (2 * theoreticalEnvelope(mid) > GAMMA * mid) shallow = mid;
    else deep = mid;
  }
  return 0.5 * (shallow + deep);
}

/** Whether the drawn surface at depth h is ever fully breaking within `sets` set periods (sampled every half second). */
function everBreaks(field: CoastField, depth: number, sets = 12): boolean {
  for (let t = 0; t < sets * SET; t += 0.5) if (coastSwellAt(field, xAtDepth(depth), 0, t).breaking >= 1) return true;
  return false;
}

/** The outermost depth where the drawn surface breaks, by bisection between 0.5 and 20 m. */
function measuredOutermostBreaking(field: CoastField): number {
  let shallow = 0.5;
  let deep = 20;
  for (let i = 0; i < 12; i++) {
    const mid = 0.5 * (shallow + deep);
    if (everBreaks(field, mid)) shallow = mid;
    else deep = mid;
  }
  return 0.5 * (shallow + deep);
}

describe('the outermost breaking: where a set’s biggest wave, 2 Σ A_m, reaches γ h', () => {
  it('lies at the depth where 2 Σ A_m = γ h by linear theory, within 15 %, deeper than a regular wave’s H_b/γ', () => {
    const expected = theoreticalOutermostBreaking();
    const measured = measuredOutermostBreaking(FIELD);
    console.log(`[oceano] outermost breaking: measured ${measured.toFixed(2)} m, 2 Σ A_m = γ h at ${expected.toFixed(2)} m`);
    expect(relativeError(measured, expected)).toBeLessThan(0.15);
    // A regular wave of Hs = 1.5 m breaks at 2.54 m; the set's biggest waves break further out.
    expect(measured).toBeGreaterThan(2.54 * 1.15);
  });

  it('a field with a planted γ = 0.5 breaks at the wrong depth and fails (negative control)', () => {
    const wrong = build({}, { ...LINEAR_THEORY, breakerIndex: 0.5 });
    expect(relativeError(measuredOutermostBreaking(wrong), theoreticalOutermostBreaking())).toBeGreaterThan(0.15);
  });
});

/** The swell summed here from each component's sampled phase and amplitude, and limited to γ h / 2: the twin's definition, rewritten. */
function summedByHand(field: CoastField, x: number, z: number, t: number, withOffsets = true): number {
  let re = 0;
  let im = 0;
  field.components.forEach((component, m) => {
    const { phase, amplitude } = sampleCoastField(field, x, z, m);
    const theta = phase - component.angularFrequency * t + (withOffsets ? component.phaseOffset : 0);
    re += amplitude * Math.cos(theta);
    im += amplitude * Math.sin(theta);
  });
  const depth = seaDepth(field.floor, x, z);
  const limit = GAMMA * Math.max(depth, 0);
  const height = 2 * Math.hypot(re, im);
  return height > limit ? (re * limit) / height : re;
}

describe('the CPU twin is the limited sum of the components', () => {
  const surface = new CoastSurface(new SeedWaveModel(defaultParams()), FIELD, FIELD.floor, false);
  const POINTS: [number, number, number][] = [
    [xAtDepth(40), 0, 3],
    [xAtDepth(8), 120, 77.5],
    [xAtDepth(2), -40, 431.25],
    [xAtDepth(0.5), 10, 12],
    [BEACH_SHORE_X + 30, 0, 5],
  ];

  it('sampleSurface’s height equals Σ A_m cos θ_m scaled by the envelope limit, and its normal that sum’s slope', () => {
    for (const [x, z, t] of POINTS) {
      const sample = surface.sample(x, z, t);
      expect(sample.height).toBeCloseTo(summedByHand(FIELD, x, z, t), 5);
      const step = 0.01;
      const slopeX = (summedByHand(FIELD, x + step, z, t) - summedByHand(FIELD, x - step, z, t)) / (2 * step);
      expect(-sample.normal[0] / sample.normal[1]).toBeCloseTo(slopeX, 3);
    }
  });

  it('a sum that forgets the phase offsets φ_m (a planted fault) disagrees with it', () => {
    const worst = Math.max(
      ...POINTS.slice(0, 3).map(([x, z, t]) => Math.abs(surface.sample(x, z, t).height - summedByHand(FIELD, x, z, t, false))),
    );
    expect(worst).toBeGreaterThan(0.05);
  });
});
