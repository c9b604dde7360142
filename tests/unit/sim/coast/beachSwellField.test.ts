import { describe, expect, it } from 'vitest';
import { BEACH_SHORE_X, OFFSHORE_DEPTH, seaDepth } from '../../../../src/sim/coast/bathymetry';
import type { CoastField, CoastSetting } from '../../../../src/sim/coast/coastField';
import { sampleCoastField } from '../../../../src/sim/coast/coastFieldSampling';
import { buildCoastField } from '../../../../src/sim/coast/coastSwellField';
import { type CoastWaveModel, LINEAR_THEORY } from '../../../../src/sim/coast/coastWaveModel';
import {
  MCCOWAN_BREAKER_INDEX,
  refractionCoefficient,
  shoalingCoefficient,
  snellAngle,
} from '../../../../src/sim/coast/waveTransformation';
import { GRAVITY, waveNumber } from '../../../../src/sim/waves/dispersion';
import { regularSwell } from '../../../../src/sim/coast/swellSpectrum';
import { crestFrontNear, crestsAlongX, heightOverPeriod, relativeError, TEST_BEACH } from '../../../support/coastSurface';

const SETTING = TEST_BEACH;
const OMEGA = (2 * Math.PI) / SETTING.swellPeriod;
const THETA0 = (SETTING.swellDirection * Math.PI) / 180;

/** A planted wrong physics: deep-water dispersion everywhere, so the waves never feel the bottom. */
const DEEP_WATER_ONLY: CoastWaveModel = {
  waveNumber: (omega) => (omega * omega) / GRAVITY,
  groupVelocity: (k) => 0.5 * Math.sqrt(GRAVITY / k),
  breakerIndex: MCCOWAN_BREAKER_INDEX,
};

/** The field of one regular wave train of the setting's height and period: linear theory's own, which these tests measure. */
const build = (setting: Partial<CoastSetting> = {}, model: CoastWaveModel = LINEAR_THEORY, resolution = 256): CoastField => {
  const full = { ...SETTING, ...setting };
  const field = buildCoastField(full, resolution, model, regularSwell(full));
  if (!field) throw new Error('a beach has a field');
  return field;
};
const xAtDepth = (depth: number, slope = SETTING.beachSlope): number => BEACH_SHORE_X - depth / slope;
const depthAt = (x: number, slope = SETTING.beachSlope): number =>
  seaDepth({ bathymetry: 'beach', beachSlope: slope, deepDepth: 60 }, x, 0);

/** The distance between the two successive crests of η around x (at z = 0, t = 0), and the depth midway. */
function measuredWavelength(field: CoastField, x: number, slope = SETTING.beachSlope): { wavelength: number; depth: number } {
  const crests = crestsAlongX(field, 0, x - 200, x + 200);
  let best = [0, 0];
  for (let c = 1; c < crests.length; c++) {
    const mid = 0.5 * (crests[c] + crests[c - 1]);
    if (c === 1 || Math.abs(mid - x) < Math.abs(0.5 * (best[0] + best[1]) - x)) best = [crests[c - 1], crests[c]];
  }
  return { wavelength: best[1] - best[0], depth: depthAt(0.5 * (best[0] + best[1]), slope) };
}

/** The crest's direction of travel at x, from one crest's front located on two lines 4 m apart in z: θ = atan(−Δx/Δz). */
function measuredAngle(field: CoastField, x: number): { angle: number; depth: number } {
  const dz = 4;
  const x0 = crestFrontNear(field, x, 0, 200);
  const x1 = crestFrontNear(field, x0, dz, 10);
  return { angle: Math.atan(-(x1 - x0) / dz), depth: depthAt(0.5 * (x0 + x1)) };
}

const DEPTHS = [40, 10, 3];
const DEG = 180 / Math.PI;

describe('beach: the local wavelength follows the dispersion relation', () => {
  for (const slope of [0.02, 0.05]) {
    it(`crest spacing at 40, 10 and 3 m equals 2π/k(h) within 3 % (slope ${slope}, head-on swell)`, () => {
      const field = build({ beachSlope: slope, swellDirection: 0 });
      for (const depth of DEPTHS) {
        const measured = measuredWavelength(field, xAtDepth(depth, slope), slope);
        const expected = (2 * Math.PI) / waveNumber(OMEGA, measured.depth);
        expect(relativeError(measured.wavelength, expected), `${depth} m`).toBeLessThan(0.03);
      }
    });
  }

  it('a field built with deep-water dispersion fails the same check in shallow water (negative control)', () => {
    const field = build({ swellDirection: 0 }, DEEP_WATER_ONLY);
    const measured = measuredWavelength(field, xAtDepth(3));
    expect(relativeError(measured.wavelength, (2 * Math.PI) / waveNumber(OMEGA, 3))).toBeGreaterThan(0.03);
  });
});

describe('beach: crests turn towards the contours by Snell', () => {
  it('the crest angle at 40, 10 and 3 m equals asin(sin θ0 · k0/k) within 2°', () => {
    const field = build();
    for (const depth of DEPTHS) {
      const measured = measuredAngle(field, xAtDepth(depth));
      const expected = snellAngle(OMEGA, THETA0, measured.depth, OFFSHORE_DEPTH);
      expect(Math.abs(measured.angle - expected) * DEG, `${depth} m`).toBeLessThan(2);
    }
  });

  it('turns with the other sign for a swell from the other side', () => {
    const measured = measuredAngle(build({ swellDirection: -30 }), xAtDepth(10));
    expect(Math.abs(measured.angle + snellAngle(OMEGA, THETA0, measured.depth, OFFSHORE_DEPTH)) * DEG).toBeLessThan(2);
  });

  it('fails against Snell at a planted wrong depth, and for a deep-water field (negative controls)', () => {
    const measured = measuredAngle(build(), xAtDepth(3));
    expect(Math.abs(measured.angle - snellAngle(OMEGA, THETA0, 2 * measured.depth, OFFSHORE_DEPTH)) * DEG, 'wrong depth').toBeGreaterThan(
      2,
    );
    const unrefracted = measuredAngle(build({}, DEEP_WATER_ONLY), xAtDepth(3));
    expect(
      Math.abs(unrefracted.angle - snellAngle(OMEGA, THETA0, unrefracted.depth, OFFSHORE_DEPTH)) * DEG,
      'deep-water field',
    ).toBeGreaterThan(2);
  });
});

/** H0 Ks Kr at depth h, for the setting's offshore height and direction. */
const shoaledHeight = (depth: number, height0 = SETTING.swellHeight): number =>
  height0 *
  shoalingCoefficient(OMEGA, depth, OFFSHORE_DEPTH) *
  refractionCoefficient(THETA0, snellAngle(OMEGA, THETA0, depth, OFFSHORE_DEPTH));

describe('beach: the height before breaking is H0 · Ks · Kr', () => {
  const HEIGHT_DEPTHS = [40, 20, 8, 3];

  it('max − min of η over a period at 40, 20, 8 and 3 m matches H0 Ks Kr within 10 %', () => {
    const field = build();
    for (const depth of HEIGHT_DEPTHS) {
      expect(relativeError(heightOverPeriod(field, xAtDepth(depth), 0), shoaledHeight(depth)), `${depth} m`).toBeLessThan(0.1);
    }
  });

  it('a deep-water field does not shoal and fails the check at 3 m (negative control)', () => {
    const field = build({}, DEEP_WATER_ONLY);
    expect(relativeError(heightOverPeriod(field, xAtDepth(3), 0), shoaledHeight(3))).toBeGreaterThan(0.1);
  });
});

/** The depth at which H0 Ks Kr reaches γ h, by bisection on linear theory. */
function theoreticalBreakingDepth(height0: number, gamma = MCCOWAN_BREAKER_INDEX): number {
  let shallow = 0.05;
  let deep = OFFSHORE_DEPTH;
  for (let i = 0; i < 60; i++) {
    const mid = 0.5 * (shallow + deep);
    if (shoaledHeight(mid, height0) > gamma * mid) shallow = mid;
    else deep = mid;
  }
  return 0.5 * (shallow + deep);
}

/** Where the wave height along the line z = 0 (max − min of η) peaks, walking from 20 m depth to the shore. */
function measuredBreakingDepth(field: CoastField): { depth: number; height: number } {
  let best = { depth: 0, height: 0 };
  for (let x = xAtDepth(20); x < BEACH_SHORE_X; x += 0.25) {
    const height = heightOverPeriod(field, x, 0, 24);
    if (height > best.height) best = { depth: depthAt(x), height };
  }
  return best;
}

describe('beach: waves break where H reaches γ h', () => {
  for (const height0 of [1, 2.5]) {
    it(`the height peaks at the depth H_b/γ within 15 % (H0 = ${height0} m), and H/h there is γ`, () => {
      const field = build({ swellHeight: height0 });
      const measured = measuredBreakingDepth(field);
      const expected = theoreticalBreakingDepth(height0);
      expect(relativeError(measured.depth, expected)).toBeLessThan(0.15);
      expect(relativeError(measured.height / measured.depth, MCCOWAN_BREAKER_INDEX)).toBeLessThan(0.15);
    });
  }

  it('the breaking fraction is 0 offshore of the breaking line and 1 inside the surf zone', () => {
    const field = build({ swellHeight: 1 });
    const depthB = theoreticalBreakingDepth(1);
    expect(sampleCoastField(field, xAtDepth(1.3 * depthB), 0).breaking).toBe(0);
    expect(sampleCoastField(field, xAtDepth(0.8 * depthB), 0).breaking).toBeCloseTo(1, 6);
    expect(sampleCoastField(field, BEACH_SHORE_X + 50, 0).amplitude).toBe(0);
  });

  it('a field with a planted γ = 0.5 breaks at the wrong depth and fails (negative control)', () => {
    const field = build({ swellHeight: 1 }, { ...LINEAR_THEORY, breakerIndex: 0.5 });
    expect(relativeError(measuredBreakingDepth(field).depth, theoreticalBreakingDepth(1))).toBeGreaterThan(0.15);
  });
});
