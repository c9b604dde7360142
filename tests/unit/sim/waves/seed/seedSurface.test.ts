import { describe, expect, it } from 'vitest';
import type { Heightmap } from '../../../../../src/sim/noise/perlinNoise';
import { defaultParams } from '../../../../../src/sim/params/params';
import { SeedWaveModel } from '../../../../../src/sim/waves/seed/seedWaveModel';
import {
  deepWaterAngularFrequency,
  maxDisplacement,
  RIPPLE_TILE_SIZE,
  sampleHeightmap,
  surfaceHeight,
  surfaceNormal,
  surfaceStateAt,
  swellHeight,
} from '../../../../../src/sim/waves/seed/seedSurface';
import { seededRandom } from '../../../../../src/sim/noise/integerHash';

const flatMaps: [Heightmap, Heightmap] = [
  { size: 4, data: new Float32Array(16) },
  { size: 4, data: new Float32Array(16) },
];

describe('swell', () => {
  const params = { ...defaultParams(), swellAmplitude: 2, swellFrequency: 0.1, rippleStrength: 0 };

  it('is A · (sin(kx) cos(kz) + 0.45 · second product) at t = 0, by the formula', () => {
    const state = surfaceStateAt(params, 0);
    const x = 3;
    const z = -7;
    const k2 = 0.1 * 1.73;
    const u = 0.8 * x + 0.6 * z;
    const v = -0.6 * x + 0.8 * z;
    const expected = 2 * (Math.sin(0.1 * x) * Math.cos(0.1 * z) + 0.45 * Math.sin(k2 * u) * Math.cos(k2 * v + 1.3));
    expect(swellHeight(state, x, z)).toBeCloseTo(expected, 12);
    expect(surfaceHeight(state, flatMaps, x, z)).toBeCloseTo(expected, 12);
  });

  it('is zero where sin(kx) and the second product vanish: at the origin, first term only', () => {
    const state = surfaceStateAt(params, 0);
    expect(swellHeight(state, 0, 0)).toBeCloseTo(2 * 0.45 * Math.sin(0) * Math.cos(1.3), 12);
  });

  it('moves with deep-water dispersion ω = √(g k)', () => {
    expect(deepWaterAngularFrequency(0.1)).toBeCloseTo(Math.sqrt(0.981), 12);
    const period = (2 * Math.PI) / deepWaterAngularFrequency(0.1);
    const state0 = surfaceStateAt(params, 0);
    const stateT = surfaceStateAt(params, period);
    expect(stateT.swellPhase[0]).toBeCloseTo(state0.swellPhase[0], 9);
  });

  it('keeps phases in [0, 2π) and offsets in one tile even at t = 10⁶ s', () => {
    const state = surfaceStateAt(params, 1e6);
    for (const phase of state.swellPhase) {
      expect(phase).toBeGreaterThanOrEqual(0);
      expect(phase).toBeLessThan(2 * Math.PI);
    }
    for (const offset of state.rippleOffset) {
      expect(offset).toBeGreaterThanOrEqual(0);
      expect(offset).toBeLessThan(RIPPLE_TILE_SIZE);
    }
  });

  it('never exceeds maxDisplacement', () => {
    const surface = new SeedWaveModel(defaultParams());
    const bound = maxDisplacement(defaultParams());
    const random = seededRandom(11);
    for (let k = 0; k < 2000; k++) {
      const { height } = surface.sample((random() - 0.5) * 4000, (random() - 0.5) * 4000, random() * 1000);
      expect(Math.abs(height)).toBeLessThanOrEqual(bound);
    }
  });
});

describe('heightmap sampling', () => {
  const map: Heightmap = { size: 2, data: new Float32Array([0, 1, 2, 3]) };

  it('returns texel values at texel positions and blends bilinearly between', () => {
    const tile = 10;
    expect(sampleHeightmap(map, tile, 0, 0)).toBeCloseTo(0, 12);
    expect(sampleHeightmap(map, tile, 5, 0)).toBeCloseTo(1, 12);
    expect(sampleHeightmap(map, tile, 0, 5)).toBeCloseTo(2, 12);
    expect(sampleHeightmap(map, tile, 2.5, 2.5)).toBeCloseTo(1.5, 12);
  });

  it('wraps: one tile further, or negative, is the same place', () => {
    for (const [x, z] of [
      [1.3, 2.2],
      [7.7, 9.1],
    ]) {
      expect(sampleHeightmap(map, 10, x + 10, z)).toBeCloseTo(sampleHeightmap(map, 10, x, z), 12);
      expect(sampleHeightmap(map, 10, x - 30, z - 10)).toBeCloseTo(sampleHeightmap(map, 10, x, z), 12);
    }
    // Between the last texel and the first, across the wrap.
    expect(sampleHeightmap(map, 10, 7.5, 0)).toBeCloseTo(0.5, 12);
  });
});

describe('fabricated-neighbour normals', () => {
  it('are straight up on a flat sea', () => {
    const state = surfaceStateAt({ ...defaultParams(), swellAmplitude: 0, rippleStrength: 0 }, 0);
    expect(surfaceNormal(state, flatMaps, 12, 34)).toEqual([-0, 1, -0]);
  });

  it('are unit length and match the analytic swell gradient when Δ is small', () => {
    const params = { ...defaultParams(), swellAmplitude: 1, swellFrequency: 0.02, rippleStrength: 0 };
    const state = { ...surfaceStateAt(params, 3), normalDelta: 1e-4 };
    const x = 17;
    const z = -9;
    const n = surfaceNormal(state, flatMaps, x, z);
    expect(Math.hypot(...n)).toBeCloseTo(1, 12);
    const e = 1e-6;
    const dhdx = (swellHeight(state, x + e, z) - swellHeight(state, x - e, z)) / (2 * e);
    const dhdz = (swellHeight(state, x, z + e) - swellHeight(state, x, z - e)) / (2 * e);
    const len = Math.hypot(dhdx, 1, dhdz);
    expect(n[0]).toBeCloseTo(-dhdx / len, 4);
    expect(n[1]).toBeCloseTo(1 / len, 4);
    expect(n[2]).toBeCloseTo(-dhdz / len, 4);
  });

  it('lean away from a rising slope: up-hill to +x tilts the normal to −x', () => {
    const ramp: Heightmap = { size: 4, data: new Float32Array([0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3]) };
    const state = surfaceStateAt({ ...defaultParams(), swellAmplitude: 0, rippleStrength: 1, rippleBlendSpeed: 0 }, 0);
    const shifted = { ...state, rippleOffset: [0, 0, 0, 0] as [number, number, number, number] };
    const n = surfaceNormal(shifted, [ramp, ramp], 10, 10);
    expect(n[0]).toBeLessThan(0);
    expect(Math.abs(n[2])).toBeLessThan(1e-12);
  });
});
