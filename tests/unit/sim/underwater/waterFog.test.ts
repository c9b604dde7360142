import { describe, expect, it } from 'vitest';
import type { Color } from 'three';
import {
  DEPTH_DARKENING,
  FOG_HIDES_BELOW,
  WATER_EXTINCTION,
  daylightAtDepth,
  fogHidingDistance,
} from '../../../../src/sim/underwater/waterFog';
import { applyWaterVolume, createWaterVolumeUniforms, setEyeDepth } from '../../../../src/render/underwater/waterVolumeUniforms';
import { SCENE_BRIGHTEST } from '../../../../src/render/underwater/sceneEncoding';
import { paramDefs } from '../../../../src/sim/params/params';
import { bodyColor } from '../../../../src/sim/optics/waterColor';
import { rgbLuminance } from '../../../support/luminance';

const transmittance = (fogDensity: number, distance: number) => WATER_EXTINCTION.map((e) => Math.exp(-fogDensity * e * distance));

describe('how far the water fog lets anything be seen (src/sim/underwater/waterFog.ts)', () => {
  // Just short of it the weakest-absorbed lets through more.
  it('at the hiding distance every channel lets through at most FOG_HIDES_BELOW', () => {
    for (const fog of [0.001, 0.035, 0.1, 0.3]) {
      const d = fogHidingDistance(fog);
      for (const t of transmittance(fog, d)) expect(t).toBeLessThanOrEqual(FOG_HIDES_BELOW * (1 + 1e-12));
      expect(Math.max(...transmittance(fog, d * 0.99))).toBeGreaterThan(FOG_HIDES_BELOW);
    }
  });

  it('is 743 m at the default density (blue, the least attenuated, sets it), and infinite without fog', () => {
    expect(paramDefs.fogDensity.default).toBe(0.035);
    expect(fogHidingDistance(0.035)).toBeCloseTo(Math.log(65536) / (WATER_EXTINCTION[2] * 0.035), 9);
    expect(fogHidingDistance(0.035)).toBeGreaterThan(742);
    expect(fogHidingDistance(0.035)).toBeLessThan(744);
    expect(fogHidingDistance(0)).toBe(Number.POSITIVE_INFINITY);
  });

  // Seen from there, over a water colour of 0.3 % of white.
  it('the brightest colour the underwater scene keeps moves the output by under half a level', () => {
    // sRGB's steepest slope above 0.003 linear: its power segment at 0.003 (1.055/2.4 · x^(1/2.4 − 1)).
    const slope = (1.055 / 2.4) * Math.pow(0.003, 1 / 2.4 - 1);
    expect(SCENE_BRIGHTEST * FOG_HIDES_BELOW * slope * 255).toBeLessThan(0.5);
  });
});

describe("the water's extinction and the daylight's fading, from pure water's optics", () => {
  // Pope & Fry 1997 absorption at 650, 510, 475 nm and Morel 1974's 0.00288 (λ/500)^−4.3 scattering.
  const a = [0.34, 0.0325, 0.0114];
  const b = [650, 510, 475].map((l) => 0.00288 * Math.pow(l / 500, -4.3));

  // The default density is pure water's c at 510 nm (control: absorption alone gives blue 0.351).
  it("extinction is c = a + b relative to green: 9.70 : 1 : 0.427, pure water's c at 510 nm", () => {
    const c = a.map((x, i) => x + b[i]);
    WATER_EXTINCTION.forEach((e, i) => expect(e).toBeCloseTo(c[i] / c[1], 9));
    expect(WATER_EXTINCTION[0]).toBeCloseTo(9.7, 2);
    expect(WATER_EXTINCTION[2]).toBeCloseTo(0.4265, 3);
    expect(paramDefs.fogDensity.default).toBeCloseTo(c[1], 3);
    expect(a[2] / a[1]).not.toBeCloseTo(WATER_EXTINCTION[2], 2);
  });

  // Control: a alone for blue is 17 % low.
  it("the daylight fades by Gordon's K_d = 1.0395 (a + b/2): 0.354, 0.0352, 0.0137 per metre", () => {
    DEPTH_DARKENING.forEach((k, i) => expect(k).toBeCloseTo(1.0395 * (a[i] + b[i] / 2), 12));
    expect(DEPTH_DARKENING[0]).toBeCloseTo(0.354, 3);
    expect(DEPTH_DARKENING[1]).toBeCloseTo(0.0352, 4);
    expect(DEPTH_DARKENING[2]).toBeCloseTo(0.0137, 4);
    expect(1.0395 * a[2]).toBeLessThan(0.87 * DEPTH_DARKENING[2]);
  });
});

describe("the daylight left at the eye's depth (the water's colour there, uWaterAtEye)", () => {
  it('fades each channel by its own exponential with depth, and is whole at and above the surface', () => {
    expect(daylightAtDepth(0)).toEqual([1, 1, 1]);
    expect(daylightAtDepth(-3)).toEqual([1, 1, 1]);
    const [r, g, b] = daylightAtDepth(10);
    expect(r).toBeCloseTo(Math.exp(-10 * DEPTH_DARKENING[0]), 12);
    expect(g).toBeCloseTo(Math.exp(-10 * DEPTH_DARKENING[1]), 12);
    expect(b).toBeCloseTo(Math.exp(-10 * DEPTH_DARKENING[2]), 12);
    // 10 m down: 3 % of the red is left, 70 % of the green, 87 % of the blue.
    expect(r).toBeCloseTo(0.029, 3);
    // Red is lost first: the deep water turns blue-green.
    expect(r).toBeLessThan(g);
    expect(g).toBeLessThan(b);
  });

  it('is the scattered colour times that daylight', () => {
    const u = createWaterVolumeUniforms();
    applyWaterVolume(u, '#0d4a5c', true, 0.8, 0.035);
    setEyeDepth(u, 6);
    const scatter = u.uWaterScatter.value as Color;
    const atEye = u.uWaterAtEye.value as Color;
    const [r, g, b] = daylightAtDepth(6);
    expect(atEye.r).toBeCloseTo(scatter.r * r, 12);
    expect(atEye.g).toBeCloseTo(scatter.g * g, 12);
    expect(atEye.b).toBeCloseTo(scatter.b * b, 12);
  });

  // The same ratios as bodyColor, and the picked default as bright (control: the picked colour is greener).
  it('is the body colour from optics unless the colour is picked', () => {
    const body = bodyColor();
    const optics = createWaterVolumeUniforms();
    applyWaterVolume(optics, '#06283a', false, 1, 0.035);
    const c = optics.uWaterScatter.value as Color;
    expect(c.r / c.b).toBeCloseTo(body[0] / body[2], 9);
    expect(c.g / c.b).toBeCloseTo(body[1] / body[2], 9);
    const picked = createWaterVolumeUniforms();
    applyWaterVolume(picked, '#06283a', true, 1, 0.035);
    const p = picked.uWaterScatter.value as Color;
    const luminance = (x: Color) => rgbLuminance(x.r, x.g, x.b);
    expect(luminance(c) / luminance(p)).toBeGreaterThan(0.98);
    expect(luminance(c) / luminance(p)).toBeLessThan(1.02);
    expect(p.g / p.b).toBeGreaterThan(1.5 * (c.g / c.b));
  });
});
