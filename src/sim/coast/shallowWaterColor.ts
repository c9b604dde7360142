import { deepWaterReflectance, molecularScattering, PURE_WATER_ABSORPTION, WAVELENGTHS } from '../optics/waterColor';

/**
 * The albedo of wet quartz sand at 650, 510 and 475 nm, a stand-in: beach sands reflect
 * 0.2–0.45 across the visible, a little more in the red than in the blue (a chosen value, not
 * a measurement of one beach).
 */
export const SAND_ALBEDO: readonly [number, number, number] = [0.42, 0.37, 0.28];

/**
 * How fast diffuse light fades in pure water, per metre, at the three wavelengths: K ≈ a + b_b
 * (absorption plus backscattering, the quasi-single-scattering estimate of the diffuse
 * attenuation; Gordon 1989). Red is gone within a few metres, blue reaches the bed of a 60 m shelf.
 */
export function diffuseAttenuation(): [number, number, number] {
  return WAVELENGTHS.map((wavelength, i) => PURE_WATER_ABSORPTION[i] + molecularScattering(wavelength) / 2) as [number, number, number];
}

/**
 * The irradiance reflectance of water `depth` metres deep over a bed of `albedo`, per
 * wavelength: the deep water's own R∞ plus what the bed adds, attenuated down and up again,
 *   R(h) = R∞ + (ρ − R∞) e^(−2 K h)
 * (the two-flow model of shallow water, Maritorena, Morel & Gentili 1994, eq. 9). Deep water
 * gives R∞, the dark blue of the open sea; a few metres over sand, the red has gone and green
 * and blue come back off the bed: turquoise. On land (depth ≤ 0) it is the bed's own albedo.
 */
export function shallowWaterReflectance(depth: number, albedo: readonly [number, number, number] = SAND_ALBEDO): [number, number, number] {
  const h = Math.max(depth, 0);
  const k = diffuseAttenuation();
  return WAVELENGTHS.map((wavelength, i) => {
    const deep = deepWaterReflectance(PURE_WATER_ABSORPTION[i], molecularScattering(wavelength));
    return deep + (albedo[i] - deep) * Math.exp(-2 * k[i] * h);
  }) as [number, number, number];
}
