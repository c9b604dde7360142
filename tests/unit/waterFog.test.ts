import { describe, expect, it } from 'vitest';
import type { Color } from 'three';
import { FOG_HIDES_BELOW, WATER_EXTINCTION, daylightAtDepth, fogHidingDistance } from '../../src/sim/underwater/waterFog';
import { applyWaterVolume, createWaterVolumeUniforms, setEyeDepth } from '../../src/render/underwater/waterVolumeUniforms';
import { SCENE_BRIGHTEST } from '../../src/render/underwater/sceneEncoding';
import { paramDefs } from '../../src/sim/params/params';

const transmittance = (fogDensity: number, distance: number) => WATER_EXTINCTION.map((e) => Math.exp(-fogDensity * e * distance));

describe('how far the water fog lets anything be seen (src/sim/underwater/waterFog.ts)', () => {
  it('at the hiding distance every channel lets through at most FOG_HIDES_BELOW, and just short of it the weakest-absorbed more', () => {
    for (const fog of [0.001, 0.035, 0.1, 0.3]) {
      const d = fogHidingDistance(fog);
      for (const t of transmittance(fog, d)) expect(t).toBeLessThanOrEqual(FOG_HIDES_BELOW * (1 + 1e-12));
      expect(Math.max(...transmittance(fog, d * 0.99))).toBeGreaterThan(FOG_HIDES_BELOW);
    }
  });

  it('is 396 m at the default density, and infinite without fog', () => {
    expect(paramDefs.fogDensity.default).toBe(0.035);
    expect(fogHidingDistance(0.035)).toBeCloseTo(Math.log(65536) / (0.8 * 0.035), 9);
    expect(fogHidingDistance(0.035)).toBeGreaterThan(395);
    expect(fogHidingDistance(0.035)).toBeLessThan(397);
    expect(fogHidingDistance(0)).toBe(Number.POSITIVE_INFINITY);
  });

  it('the brightest colour the underwater scene keeps, seen from there, moves the output by under half a level over a water colour of 0.3 % of white', () => {
    // sRGB's steepest slope above 0.003 linear: its power segment at 0.003 (1.055/2.4 · x^(1/2.4 − 1)).
    const slope = (1.055 / 2.4) * Math.pow(0.003, 1 / 2.4 - 1);
    expect(SCENE_BRIGHTEST * FOG_HIDES_BELOW * slope * 255).toBeLessThan(0.5);
  });
});

describe("the daylight left at the eye's depth (the water's colour there, uWaterAtEye)", () => {
  it('fades each channel by its own exponential with depth, and is whole at and above the surface', () => {
    expect(daylightAtDepth(0)).toEqual([1, 1, 1]);
    expect(daylightAtDepth(-3)).toEqual([1, 1, 1]);
    const [r, g, b] = daylightAtDepth(10);
    expect(r).toBeCloseTo(Math.exp(-1.2), 12);
    expect(g).toBeCloseTo(Math.exp(-0.45), 12);
    expect(b).toBeCloseTo(Math.exp(-0.3), 12);
    // Red is lost first: the deep water turns blue-green.
    expect(r).toBeLessThan(g);
    expect(g).toBeLessThan(b);
  });

  it('is the scattered colour times that daylight', () => {
    const u = createWaterVolumeUniforms();
    applyWaterVolume(u, '#0d4a5c', 0.8, 0.035);
    setEyeDepth(u, 6);
    const scatter = u.uWaterScatter.value as Color;
    const atEye = u.uWaterAtEye.value as Color;
    const [r, g, b] = daylightAtDepth(6);
    expect(atEye.r).toBeCloseTo(scatter.r * r, 12);
    expect(atEye.g).toBeCloseTo(scatter.g * g, 12);
    expect(atEye.b).toBeCloseTo(scatter.b * b, 12);
  });
});
