import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  MIN_PREFILTERED_SIZE,
  PREFILTER_OVERSAMPLING,
  prefilteredFaceSize,
  skyBlurLevel,
  slopeVarianceAtLevel,
} from '../../../../src/sim/optics/skyBlurLevel';

/** The mip level a rough mirror reads, and the size of the cube that holds the sky as it shows it (src/render/sky/prefilteredSky.ts). */
describe("the sky's blur level and the prefiltered cube's size", () => {
  // √(2σ²) = w/√12 texels of a π/2-wide face.
  it('reads the level whose box spreads a ray as far as facets of σ² turn it', () => {
    // 9.73 is 24 / (π/2)²: the box w = faceSize √(24 σ²) / (π/2).
    expect(24 / (Math.PI / 2) ** 2).toBeCloseTo(9.73, 2);
    const turn = Math.sqrt(0.02 * 2);
    const boxTexels = 2 ** skyBlurLevel(512, 0.02);
    expect(((boxTexels / Math.sqrt(12)) * (Math.PI / 2)) / 512).toBeCloseTo(turn, 3);
    // A facet spread that covers the whole face reads the 1 × 1 level; a mirror reads level 0 (never below).
    expect(skyBlurLevel(512, 1 / 9.73)).toBeCloseTo(9, 12);
    expect(skyBlurLevel(512, 0)).toBe(0);
  });

  it('is the formula shaders/skyCube.glsl evaluates per pixel', () => {
    const glsl = readFileSync(new URL('../../../../shaders/skyCube.glsl', import.meta.url), 'utf8');
    expect(glsl).toContain('log2(float(textureSize(uSky, 0).x) * sqrt(9.73 * variance))');
  });

  // At least 32 texels and at most the sky's own.
  it('holds the finer of the two levels blended at 8 times its resolution', () => {
    expect([PREFILTER_OVERSAMPLING, MIN_PREFILTERED_SIZE]).toEqual([8, 32]);
    for (const variance of [2.7e-6, 1e-4, 1e-3, 0.005, 0.02, 0.04, 0.08]) {
      const finer = 512 / 2 ** Math.floor(skyBlurLevel(512, variance));
      const size = prefilteredFaceSize(512, variance);
      expect(size).toBe(Math.min(512, Math.max(32, 8 * finer)));
      expect(Number.isInteger(Math.log2(size))).toBe(true);
    }
    // The seed's sea at 10 m/s leaves σ² ≈ 0.048 unresolved: level 8.45 (2 texels a face), so a 32-texel cube.
    expect(skyBlurLevel(512, 0.048)).toBeCloseTo(8.45, 2);
    expect(prefilteredFaceSize(512, 0.048)).toBe(32);
    // The windless mirror (the sun's disc only) keeps the whole sky.
    expect(prefilteredFaceSize(512, 2.7e-6)).toBe(512);
  });

  // The prefiltered cube rounds the level to a 64th.
  it('finds the mean-square slope that reads a given level, its inverse', () => {
    for (const level of [0.5, 3, 8.453125, 9]) expect(skyBlurLevel(512, slopeVarianceAtLevel(512, level))).toBeCloseTo(level, 12);
    // A 64th of a level is a 2.2 % change of σ²; the seed's roughness at 10 m/s spans 0.02 of a level over 20 s.
    expect(slopeVarianceAtLevel(512, 8 + 1 / 64) / slopeVarianceAtLevel(512, 8)).toBeCloseTo(1.0219, 4);
  });
});
