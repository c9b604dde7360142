import { GRAVITY } from './dispersion';

/**
 * Linear (Airy) wave theory for one wave η = a cos(kx − ωt) (Airy 1845; Dean & Dalrymple 1991,
 * ch. 3–4). Under it each water particle runs round an orbit whose semi-axes shrink with depth;
 * the sea on screen draws only the surface, z = 0, where both equal a in deep water.
 */

/** Density of sea water, kg/m³. */
export const SEA_WATER_DENSITY = 1025;

/**
 * Semi-axes (m) of the orbit of a particle whose rest position is z metres below the surface
 * (z ≤ 0) under a wave of amplitude a and wavenumber k over water of depth h:
 * horizontal a cosh k(z+h) / sinh kh, vertical a sinh k(z+h) / sinh kh, both a e^{kz} in deep water.
 */
export function orbitSemiAxes(a: number, k: number, z: number, depth = Number.POSITIVE_INFINITY): { horizontal: number; vertical: number } {
  // Beyond kh = 20 the hyperbolic ratios equal e^{kz} to double precision.
  if (!Number.isFinite(depth) || k * depth > 20) return { horizontal: a * Math.exp(k * z), vertical: a * Math.exp(k * z) };
  const s = Math.sinh(k * depth);
  return { horizontal: (a * Math.cosh(k * (z + depth))) / s, vertical: (a * Math.sinh(k * (z + depth))) / s };
}

/** Mean energy per unit area (J/m²) of a wave of amplitude a: E = ½ ρ g a², half of it kinetic, half potential. */
export function waveEnergy(a: number, density = SEA_WATER_DENSITY, gravity = GRAVITY): number {
  return 0.5 * density * gravity * a * a;
}
