import { deepWaterReflectance, molecularScattering, PURE_WATER_ABSORPTION, WAVELENGTHS } from '../optics/waterColor';

/**
 * The albedo of the sand at 650, 510 and 475 nm: the sea bed's colour under the water
 * (src/render/underwater/seaBed.ts), a chosen value, not a measurement of one beach (sands
 * reflect 0.2–0.6, more in the red than in the blue).
 */
export const SAND_ALBEDO: readonly [number, number, number] = [0.55, 0.47, 0.33];

/**
 * What coastal water holds beside the water itself (plankton, dissolved matter, fine sediment)
 * adds to the diffuse attenuation, per metre, alike at every wavelength: a chosen value for a
 * clean coast (Jerlov's coastal waters attenuate blue-green light 0.05–0.3 m⁻¹ more than the
 * clearest ocean). Pure water alone would show the bed of a 60 m shelf.
 */
export const COASTAL_EXTRA_ATTENUATION = 0.06;

/**
 * How fast diffuse light fades in the coast's water, per metre, at the three wavelengths:
 * K ≈ a + b_b (absorption plus backscattering, the quasi-single-scattering estimate of the
 * diffuse attenuation; Gordon 1989) of pure water, plus COASTAL_EXTRA_ATTENUATION.
 */
export function diffuseAttenuation(): [number, number, number] {
  return WAVELENGTHS.map((wavelength, i) => PURE_WATER_ABSORPTION[i] + molecularScattering(wavelength) / 2 + COASTAL_EXTRA_ATTENUATION) as [
    number,
    number,
    number,
  ];
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
