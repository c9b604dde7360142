/**
 * The colour of deep, clear sea water from its optics, at three wavelengths standing for the
 * screen's red, green and blue (650, 510, 475 nm), as Tessendorf ("Simulating Ocean Water",
 * §"Colour") and Jensen & Golias ("Deep-Water Animation and Rendering", 2001) derive it:
 * light that enters the water is absorbed (a) or scattered (b); what is scattered back up
 * before it is absorbed is the water's own colour.
 */

/** The three wavelengths, nm: red, green, blue. */
export const WAVELENGTHS: readonly [number, number, number] = [650, 510, 475];

/**
 * Absorption of pure water, m⁻¹, at 650, 510 and 475 nm (Pope, R. M. & Fry, E. S. 1997,
 * "Absorption spectrum (380–700 nm) of pure water. II. Integrating cavity measurements",
 * Appl. Opt. 36(33), 8710–8723, Table 3): red light is gone within metres, blue travels ~90 m.
 */
export const PURE_WATER_ABSORPTION: readonly [number, number, number] = [0.34, 0.0325, 0.0114];

/**
 * Scattering by the water molecules themselves, m⁻¹: b(λ) = 0.00288 (λ / 500 nm)^−4.3
 * (Morel, A. 1974, "Optical properties of pure water and pure sea water", in Optical Aspects
 * of Oceanography, Jerlov & Steemann Nielsen (eds.), 1–24): Rayleigh-like, steeper than λ⁻⁴
 * because the refractive index varies with λ too.
 */
export function molecularScattering(wavelength: number): number {
  return 0.00288 * Math.pow(wavelength / 500, -4.3);
}

/**
 * The irradiance reflectance just below the surface of deep water, R = f b_b / (a + b_b),
 * in single scattering with the molecules' symmetric phase function (b_b = b/2) and Morel &
 * Prieur's f = 0.33 (Morel, A. & Prieur, L. 1977, "Analysis of variations in ocean color",
 * Limnol. Oceanogr. 22(4), 709–722, eq. 4, for a sun high in the sky).
 */
export const REFLECTANCE_FACTOR = 0.33;

export function deepWaterReflectance(absorption: number, scattering: number): number {
  const backscattering = scattering / 2;
  return (REFLECTANCE_FACTOR * backscattering) / (absorption + backscattering);
}

/** R at the three wavelengths, red, green, blue: the body colour of deep clear water, per unit down-welling light. */
export function bodyColor(): [number, number, number] {
  return WAVELENGTHS.map((wavelength, i) => deepWaterReflectance(PURE_WATER_ABSORPTION[i], molecularScattering(wavelength))) as [
    number,
    number,
    number,
  ];
}
