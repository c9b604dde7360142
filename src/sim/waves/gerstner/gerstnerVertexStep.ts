import { gerstnerWavenumber } from './gerstnerSlopes';
import type { GerstnerWave } from './gerstnerWaves';

/**
 * Vertices per wavelength a steep wave needs. Between vertices the mesh is flat while the
 * per-pixel normal follows the wave; with a wave only a few vertex steps long, the slope facing
 * away from a low eye, which the crest would hide on the true surface, shows on the coarse
 * triangles as pale shelves. Measured in the gerstner-steepness lesson (the share of the sea's
 * pixels whose normal faces away from the eye): 12.5 % with 2 m between vertices (a 3.9 m
 * crest drawn from two), 2.1 % at 1 m, 0.5 % at 0.5 m (docs/light.md).
 */
export const VERTICES_PER_STEEP_WAVE = 8;

/**
 * A wave is steep where the trochoid's steepest slope, Ak / √(1 − q²) (q = QAk, at
 * cos θ = q), reaches this: 8.5°. A sea of 32 waves from a spectrum stays below it at any wind
 * (each wave's Ak is at most 0.07); the lessons' 4-wave seas reach 0.3–0.5.
 */
export const STEEP_SLOPE = 0.15;

/** The vertex spacing, metres, the steep waves need (the shortest of them over VERTICES_PER_STEEP_WAVE); Infinity when none is steep. */
export function gerstnerFinestVertexStep(waves: readonly GerstnerWave[]): number {
  let step = Infinity;
  for (const wave of waves) {
    const k = gerstnerWavenumber(wave);
    const q = Math.min(wave.horizontal * k, 0.999);
    if ((wave.amplitude * k) / Math.sqrt(1 - q * q) >= STEEP_SLOPE) step = Math.min(step, (2 * Math.PI) / k / VERTICES_PER_STEEP_WAVE);
  }
  return step;
}
