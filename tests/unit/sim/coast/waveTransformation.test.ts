import { describe, expect, it } from 'vitest';
import {
  breakingDepth,
  breakingFraction,
  breakingHeight,
  MCCOWAN_BREAKER_INDEX,
  rayTubeCoefficient,
  refractionCoefficient,
  shoalingCoefficient,
  snellAngle,
} from '../../../../src/sim/coast/waveTransformation';
import { GRAVITY, waveNumber } from '../../../../src/sim/waves/dispersion';

const PERIOD = 10;
const OMEGA = (2 * Math.PI) / PERIOD;
/** The deep-water wavelength L0 = g T² / 2π. */
const L0 = (GRAVITY * PERIOD * PERIOD) / (2 * Math.PI);
const DEEP = Number.POSITIVE_INFINITY;

describe('published values of shoaling and dispersion in Dean & Dalrymple 1991, tables', () => {
  it('h/L0 = 0.1 gives h/L = 0.1410', () => {
    const depth = 0.1 * L0;
    expect((depth * waveNumber(OMEGA, depth)) / (2 * Math.PI)).toBeCloseTo(0.141, 3);
  });

  it('Ks falls to its minimum 0.913 near h/L0 = 0.15 and is back to about 1.02 at h/L0 = 0.05', () => {
    let minimum = { ks: Infinity, ratio: 0 };
    for (let ratio = 0.02; ratio < 0.5; ratio += 0.001) {
      const ks = shoalingCoefficient(OMEGA, ratio * L0, DEEP);
      if (ks < minimum.ks) minimum = { ks, ratio };
    }
    expect(minimum.ks).toBeCloseTo(0.913, 3);
    expect(Math.abs(minimum.ratio - 0.15)).toBeLessThan(0.015);
    expect(shoalingCoefficient(OMEGA, 0.05 * L0, DEEP)).toBeCloseTo(1.02, 2);
  });

  it('a planted wrong depth (twice as deep) misses the table value (negative control)', () => {
    const depth = 0.1 * L0;
    expect(Math.abs((depth * waveNumber(OMEGA, 2 * depth)) / (2 * Math.PI) - 0.141)).toBeGreaterThan(0.01);
    expect(Math.abs(shoalingCoefficient(OMEGA, 0.1 * L0, DEEP) - 1.02)).toBeGreaterThan(0.05);
  });
});

describe("Snell's law and the refraction coefficient", () => {
  it('sin θ / c is the same at every depth', () => {
    const theta0 = (40 * Math.PI) / 180;
    const invariant = (depth: number): number => Math.sin(snellAngle(OMEGA, theta0, depth, 60)) * waveNumber(OMEGA, depth);
    for (const depth of [40, 10, 3, 1]) expect(invariant(depth)).toBeCloseTo(invariant(60), 12);
    expect(snellAngle(OMEGA, theta0, 3, 60)).toBeLessThan(theta0);
  });

  it('Kr = √(cos θ0 / cos θ) equals the ray-tube √(b0 / b) for straight contours, where b ∝ cos θ', () => {
    const theta0 = (30 * Math.PI) / 180;
    const theta = snellAngle(OMEGA, theta0, 3, 60);
    expect(refractionCoefficient(theta0, theta)).toBeCloseTo(rayTubeCoefficient(Math.cos(theta0), Math.cos(theta)), 12);
    expect(refractionCoefficient(theta0, theta)).toBeLessThan(1);
    expect(refractionCoefficient(theta0, theta0)).toBe(1);
  });
});

describe("McCowan's breaking", () => {
  it('γ = 0.78: a 1.56 m wave breaks in 2 m of water, and 2 m carries at most 1.56 m', () => {
    expect(MCCOWAN_BREAKER_INDEX).toBe(0.78);
    expect(breakingDepth(1.56)).toBeCloseTo(2, 12);
    expect(breakingHeight(2)).toBeCloseTo(1.56, 12);
    expect(breakingHeight(-1)).toBe(0);
  });

  it('the breaking fraction ramps from 0 at 0.9 γ h to 1 at γ h', () => {
    expect(breakingFraction(0.89 * 0.78 * 2, 2)).toBe(0);
    expect(breakingFraction(0.95 * 0.78 * 2, 2)).toBeCloseTo(0.5, 12);
    expect(breakingFraction(0.78 * 2, 2)).toBe(1);
    expect(breakingFraction(3, 2)).toBe(1);
  });

  it('a planted γ of 0.55 (Miche) puts the same wave in deeper water (negative control)', () => {
    expect(Math.abs(breakingDepth(1.56, 0.55) - 2) / 2).toBeGreaterThan(0.15);
  });
});
