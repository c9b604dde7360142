import type { SeaFloor } from './bathymetry';

/**
 * The swell near the coast as linear wave theory gives it, precomputed once per setting on a
 * square grid of texels over the coast (the region where the bottom is felt). The GPU draws
 * the swell from these grids uploaded as a texture, and the CPU twin reads the same grids with
 * the same bilinear interpolation, so both see one surface.
 *
 * At a point the swell is a plane wave of local phase S(x, z) (radians, unwrapped, so bilinear
 * interpolation is smooth) and amplitude a(x, z):
 *   η = a cos(S − ω t),  with |∇S| = k(h) from ω² = g k tanh(k h).
 * Outside the grid the swell is the plane wave of the offshore depth, continuing the grid's
 * edge.
 */
export interface SwellSettings {
  /** The swell's wave height H = 2a offshore, metres (0: no swell). */
  swellHeight: number;
  /** The swell's period, seconds. */
  swellPeriod: number;
  /** The direction the swell travels, degrees: 0 heads straight for the beach's shore (+x), 90 along +z. */
  swellDirection: number;
}

export interface CoastField {
  /** World x and z of texel (0, 0)'s centre, and the metres between texel centres. */
  originX: number;
  originZ: number;
  spacing: number;
  /** Texels per side. */
  resolution: number;
  /** ω = 2π / swellPeriod, rad/s. */
  angularFrequency: number;
  /**
   * Four floats per texel, row-major in z then x (texel (i, j) at [(j * resolution + i) * 4]):
   * the unwrapped phase S (rad), the amplitude a (m, after shoaling, refraction and breaking),
   * the depth h (m, ≤ 0 on land) and the breaking fraction (0: unbroken, 1: breaking).
   */
  texels: Float32Array;
}

export interface CoastSetting extends SeaFloor, SwellSettings {}
