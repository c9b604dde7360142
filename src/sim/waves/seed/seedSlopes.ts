import type { Heightmap } from '../../noise/perlinNoise';
import { NORMAL_DELTA, RIPPLE_TILE_SIZE, sampleHeightmap, SECOND_SWELL, type SurfaceState } from './seedSurface';

/**
 * The mean-square slope of the seed's sea as its normals show it (both horizontal directions
 * summed, as Cox & Munk count it): what the sea's pixels resolve, of which the rest of Cox &
 * Munk's σ² becomes the glint's roughness (shaders/waves/seed.glsl).
 */

/**
 * The swell: A sin(kx + a) cos(kz + b) has ∂/∂x = Ak cos·cos and ∂/∂z = −Ak sin·sin, each of
 * mean square A²k²/4 over a period, A²k²/2 in all; the second product (0.45 A, 1.73 k, turned)
 * adds its own, and the two are uncorrelated (different wavevectors).
 */
export function swellSlopeVariance(amplitude: number, frequency: number): number {
  const second = SECOND_SWELL.amplitude * SECOND_SWELL.frequency;
  return ((amplitude * frequency) ** 2 / 2) * (1 + second * second);
}

/**
 * A ripple heightmap's mean-square slope (at unit strength) as the fabricated normal takes
 * it: the difference quotients (H(x + Δ, z) − H(x, z)) / Δ and (H(x, z + Δ) − H(x, z)) / Δ of
 * the bilinear field, squared and summed, averaged over one tile at every texel's centre.
 */
export function heightmapSlopeVariance(map: Heightmap, tileSize = RIPPLE_TILE_SIZE, delta = NORMAL_DELTA): number {
  const step = tileSize / map.size;
  let sum = 0;
  for (let j = 0; j < map.size; j++) {
    for (let i = 0; i < map.size; i++) {
      const x = (i + 0.5) * step;
      const z = (j + 0.5) * step;
      const h = sampleHeightmap(map, tileSize, x, z);
      sum += (sampleHeightmap(map, tileSize, x + delta, z) - h) ** 2 + (sampleHeightmap(map, tileSize, x, z + delta) - h) ** 2;
    }
  }
  return sum / (map.size * map.size * delta * delta);
}

/**
 * The whole sea's at a state: the swell's, plus the ripples', strength² ((1 − w)² V₀ + w² V₁)
 * for the blend w of two maps whose slopes are uncorrelated (independent noise, drifting
 * apart; the cross term is left out, within 10 % of the ripples' share, tests/unit/sim/waves/seed/seedSlopes.test.ts).
 */
export function seedSlopeVariance(state: SurfaceState, heightmapVariances: readonly [number, number]): number {
  const w = state.rippleBlend;
  const ripples = (1 - w) ** 2 * heightmapVariances[0] + w * w * heightmapVariances[1];
  return swellSlopeVariance(state.swellAmplitude, state.swellFrequency) + state.rippleStrength ** 2 * ripples;
}
