import { describe, expect, it } from 'vitest';
import { HIGHLIGHT_KNEE, rollOffHighlight } from '../../../../src/sim/optics/highlightRollOff';
import {
  SUN_DISC_COS_CORE,
  SUN_DISC_COS_EDGE,
  SUN_DISC_COS_MID,
  SUN_DISC_SOLID_ANGLE,
  sunDiscRadiance,
} from '../../../../src/sim/optics/sunDisc';
import { SUN_IRRADIANCE } from '../../../../src/sim/optics/sun';

const slope = (f: (x: number) => number, x: number, h = 1e-6) => (f(x + h) - f(x - h)) / (2 * h);

/** Whether a curve keeps lights from 1 to 2.5 times white apart on screen (by a thousandth, a quarter of an 8-bit level or more): the glint's falloff above white stays visible. */
function keepsOrderAboveWhite(curve: (x: number) => number): boolean {
  const lights = [1, 1.5, 2, 2.5];
  return lights.every((x, i) => i === 0 || curve(x) > curve(lights[i - 1]) + 1e-3);
}

describe("the whole frame's tone curve: the highlight roll-off", () => {
  it('leaves every colour below the knee exactly as it is', () => {
    for (let x = 0; x <= HIGHLIGHT_KNEE; x += 0.01) expect(rollOffHighlight(x)).toBe(x);
  });

  it('is continuous with slope 1 at the knee, monotonic, and below white for any finite light', () => {
    const h = 1e-5;
    expect(rollOffHighlight(HIGHLIGHT_KNEE + h) - rollOffHighlight(HIGHLIGHT_KNEE)).toBeCloseTo(h, 9);
    expect(slope(rollOffHighlight, HIGHLIGHT_KNEE + 1e-4)).toBeCloseTo(1, 3);
    let previous = 0;
    for (let x = 0.01; x < 10; x *= 1.1) {
      const y = rollOffHighlight(x);
      expect(y).toBeGreaterThan(previous);
      expect(y).toBeLessThan(1);
      previous = y;
    }
    // Radiance 1 (the sky cube's white) shows as 0.853, the sun's disc (about 5,500) as white.
    expect(rollOffHighlight(1)).toBeCloseTo(0.6 + 0.4 * (1 - Math.exp(-1)), 12);
    expect(rollOffHighlight(sunDiscRadiance(SUN_IRRADIANCE))).toBeCloseTo(1, 12);
  });

  it('keeps lights brighter than white in order; control: clipping at white does not', () => {
    expect(keepsOrderAboveWhite(rollOffHighlight)).toBe(true);
    expect(keepsOrderAboveWhite((x) => Math.min(x, 1))).toBe(false);
  });
});

describe("the sun's disc in full brightness", () => {
  /** 2π ∫ coverage d(cos θ) for the drawn disc's smoothstep edge, by the midpoint rule. */
  function drawnSolidAngle(edge: number, core: number): number {
    const steps = 100_000;
    const from = edge - 1e-5;
    const width = (1 - from) / steps;
    let sum = 0;
    for (let i = 0; i < steps; i++) {
      const mu = from + (i + 0.5) * width;
      const t = Math.min(1, Math.max(0, (mu - edge) / (core - edge)));
      sum += t * t * (3 - 2 * t) * width;
    }
    return 2 * Math.PI * sum;
  }

  it('has the solid angle of the disc the sky cube draws, and the sharp disc to the middle of its edge has the same', () => {
    expect(drawnSolidAngle(SUN_DISC_COS_EDGE, SUN_DISC_COS_CORE) / SUN_DISC_SOLID_ANGLE).toBeCloseTo(1, 5);
    expect(SUN_DISC_SOLID_ANGLE).toBeCloseTo(2 * Math.PI * (1 - SUN_DISC_COS_MID), 15);
    expect(SUN_DISC_SOLID_ANGLE).toBeCloseTo(7.23e-4, 5);
  });

  it("gives back the sun's irradiance over that solid angle; control: the real disc's size does not", () => {
    expect(sunDiscRadiance(SUN_IRRADIANCE) * SUN_DISC_SOLID_ANGLE).toBeCloseTo(SUN_IRRADIANCE, 12);
    const realDisc = Math.PI * 0.00465 ** 2;
    expect(Math.abs(sunDiscRadiance(SUN_IRRADIANCE) * realDisc - SUN_IRRADIANCE)).toBeGreaterThan(1);
  });
});
