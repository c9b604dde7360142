import type { SeaFloor } from './bathymetry';

/**
 * The swell near the coast as linear wave theory gives it, precomputed once per setting on a
 * square grid of texels over the coast (the region where the bottom is felt). The GPU draws
 * the swell from these grids uploaded as a texture, and the CPU twin reads the same grids with
 * the same bilinear interpolation, so both see one surface.
 *
 * The swell is a sum of components (swellSpectrum.ts), each a wave train of its own frequency
 * ω_m transformed by the floor: at a point, component m has local phase S_m(x, z) (radians,
 * unwrapped, so bilinear interpolation is smooth) and amplitude A_m(x, z) = a_m Ks Kr, with
 * |∇S_m| = k_m(h) from ω_m² = g k tanh(k h), and no breaking yet. Together they are the real
 * part of Z = Σ A_m e^{i(S_m − ω_m t + φ_m)}, and where the envelope 2|Z| exceeds γ h the sum
 * is scaled down to it (coastSwellSlope.ts): the breaking of the group.
 * Outside the grid each component is the plane wave of the offshore depth, continuing the
 * grid's edge.
 */
export interface SwellSettings {
  /** The swell's significant height Hs = 4 √m0 offshore, metres (0: no swell). */
  swellHeight: number;
  /** The swell's peak period Tp, seconds. */
  swellPeriod: number;
  /** The direction the swell travels, degrees: 0 heads straight for the beach's shore (+x), 90 along +z. */
  swellDirection: number;
  /** The app's seed: the components' phase offsets (the same seed, the same sets). */
  seed: number;
}

/** One component of the swell over the grid. */
export interface SwellComponentField {
  /** ω_m, rad/s. */
  angularFrequency: number;
  /** φ_m, radians. */
  phaseOffset: number;
  /**
   * Two floats per texel, row-major in z then x (texel (i, j) at [(j * resolution + i) * 2]):
   * the unwrapped phase S (rad) and the amplitude A (m, after shoaling and refraction, before
   * breaking; 0 on land).
   */
  texels: Float32Array;
}

export interface CoastField {
  /** World x and z of texel (0, 0)'s centre, and the metres between texel centres. */
  originX: number;
  originZ: number;
  spacing: number;
  /** Texels per side. */
  resolution: number;
  /** The floor the field was built over: its depth is analytic (seaDepth), on the GPU too. */
  floor: SeaFloor;
  /** γ: the envelope 2|Z| is limited to γ h. */
  breakerIndex: number;
  components: SwellComponentField[];
}

export interface CoastSetting extends SeaFloor, SwellSettings {}
