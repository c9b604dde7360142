import { describe, expect, it } from 'vitest';
import { generateRippleHeightmaps } from '../../../../../src/sim/noise/perlinNoise';
import { defaultParams } from '../../../../../src/sim/params/params';
import { heightmapSlopeVariance, seedSlopeVariance, swellSlopeVariance } from '../../../../../src/sim/waves/seed/seedSlopes';
import {
  HEIGHTMAP_SIZE,
  NORMAL_DELTA,
  RIPPLE_TILE_SIZE,
  surfaceNormal,
  surfaceStateAt,
  type SurfaceState,
} from '../../../../../src/sim/waves/seed/seedSurface';
import { SeedWaveModel } from '../../../../../src/sim/waves/seed/seedWaveModel';

/**
 * The seed's mean-square slope in closed form (the swell) and from its heightmaps (the
 * ripples) against brute force: the CPU twin's own fabricated normals sampled densely,
 * tan² of their tilt averaged. These are the slopes the glint's roughness is Cox & Munk's
 * σ² less.
 */
function measured(state: SurfaceState, maps: ReturnType<typeof generateRippleHeightmaps>, extent: number, samples: number): number {
  let sum = 0;
  for (let j = 0; j < samples; j++) {
    for (let i = 0; i < samples; i++) {
      const [nx, ny, nz] = surfaceNormal(state, maps, ((i + 0.37) * extent) / samples, ((j + 0.61) * extent) / samples);
      sum += (nx * nx + nz * nz) / (ny * ny);
    }
  }
  return sum / (samples * samples);
}

describe('the seed sea’s resolved slopes', () => {
  const params = defaultParams();
  const maps = generateRippleHeightmaps(params.seed, HEIGHTMAP_SIZE);

  it('the swell’s is A²k²/2 (1 + (0.45 · 1.73)²), over whole periods; control: one axis only (A²k²/4) fails', () => {
    const state = surfaceStateAt({ ...params, rippleStrength: 0 }, 3.7);
    // The two products repeat together only far out; 16 of the first's periods average both well.
    const extent = (16 * 2 * Math.PI) / state.swellFrequency;
    const brute = measured(state, maps, extent, 400);
    expect(swellSlopeVariance(state.swellAmplitude, state.swellFrequency) / brute).toBeCloseTo(1, 2);
    expect(Math.abs((((state.swellAmplitude * state.swellFrequency) ** 2 / 4) * 1.6061) / brute - 1)).toBeGreaterThan(0.3);
  });

  // At blends 0–1; the two maps’ slopes correlate a little at some offsets (up to 9 % at t = 20 s). Control:
  // linear weights fail at mid-blend.
  it('the ripples’ follows each map’s variance and the blend’s squared weights, within 10 %', () => {
    const variances: [number, number] = [
      heightmapSlopeVariance(maps[0], RIPPLE_TILE_SIZE, NORMAL_DELTA),
      heightmapSlopeVariance(maps[1], RIPPLE_TILE_SIZE, NORMAL_DELTA),
    ];
    const ripplesOnly = { ...params, swellAmplitude: 0 };
    let controlWorst = 0;
    // rippleBlend = ½ − ½ cos(0.25 t): t = 0, 2π, 4π/… gives w = 0, ½, 1 and between.
    for (const t of [0, 3, 2 * Math.PI, 9, 4 * Math.PI, 20, 30]) {
      const state = surfaceStateAt(ripplesOnly, t);
      const brute = measured(state, maps, RIPPLE_TILE_SIZE, 192);
      expect(Math.abs(seedSlopeVariance(state, variances) / brute - 1)).toBeLessThan(0.1);
      const w = state.rippleBlend;
      const linear = state.rippleStrength ** 2 * ((1 - w) * variances[0] + w * variances[1]);
      controlWorst = Math.max(controlWorst, Math.abs(linear / brute - 1));
    }
    expect(controlWorst).toBeGreaterThan(0.3);
  });

  // Swell and ripples: 0.006, against Cox & Munk’s 0.055 at 10 m/s.
  it('the model reports the whole sea’s at its default parameters, far below Cox & Munk’s', () => {
    const model = new SeedWaveModel(params);
    const state = surfaceStateAt(params, 10);
    const brute = measured(state, maps, 2 * RIPPLE_TILE_SIZE * 4, 600);
    expect(Math.abs(model.slopeVariance(10) / brute - 1)).toBeLessThan(0.1);
    expect(model.slopeVariance(10)).toBeGreaterThan(0.004);
    expect(model.slopeVariance(10)).toBeLessThan(0.01);
  });
});
