/**
 * How much light thick, fresh sea foam (a whitecap's white) reflects, at the three wavelengths
 * that stand for the screen's red, green and blue (WAVELENGTHS in waterColor.ts).
 *
 * Foam is a pile of bubbles: light is scattered many times by their films and crosses a little
 * water on the way, so foam is white where water absorbs little and darker where it absorbs
 * more. Two measurements fix it:
 * - its level: about 0.55 over the visible for fresh, thick foam (Whitlock, C. H., Bartlett,
 *   D. S. & Gurganus, E. A. 1982, "Sea foam reflectance", Geophys. Res. Lett. 9(6), 719–722);
 *   thinner and older whitecaps reflect less, about 0.4 on average (Dierssen, H. M. 2019,
 *   Front. Earth Sci. 7:14), which the foam material draws as lace over the water;
 * - its fall with wavelength: 40 % lower at 850 nm than in the visible (Frouin, R.,
 *   Schwindling, M. & Deschamps, P.-Y. 1996, "Spectral reflectance of sea foam in the visible
 *   and near-infrared", J. Geophys. Res. 101(C6), 14361–14371).
 *
 * Here the fall is water's absorption along an effective path through the foam, R(λ) =
 * R_visible · e^{−a(λ) L}, with L fitted to Frouin's 850 nm figure. In the visible the
 * absorption is small (Pope & Fry's a at 650 nm is 0.34 m⁻¹), so foam comes out almost grey,
 * red a few per cent lower than blue: thick foam's visible bands "tend to equalize" (Moore,
 * K. D., Voss, K. J. & Gordon, H. R. 1998, J. Atmos. Oceanic Technol. 15(2), 496–509). The one-path form is only a fit: past 1 µm it falls far faster than
 * measured, which a screen never shows.
 */
import { PURE_WATER_ABSORPTION } from './waterColor';

/** Reflectance of fresh, thick foam over the visible (Whitlock et al. 1982). */
export const FOAM_VISIBLE_REFLECTANCE = 0.55;

/**
 * Absorption of pure water at 850 nm, m⁻¹ (Kou, L., Labrie, D. & Chylek, P. 1993, "Refractive
 * indices of water and ice in the 0.65- to 2.5-µm spectral range", Appl. Opt. 32(19), 3531–3540).
 */
export const WATER_ABSORPTION_850NM = 4.3;

/** Foam's reflectance at 850 nm over its reflectance in the visible (Frouin et al. 1996). */
export const FOAM_850NM_OVER_VISIBLE = 0.6;

/** The effective path through water, m, that makes e^{−a(850) L} Frouin's 0.6: about 12 cm. */
export const FOAM_WATER_PATH = -Math.log(FOAM_850NM_OVER_VISIBLE) / WATER_ABSORPTION_850NM;

/** Foam's reflectance where water absorbs `absorption` m⁻¹. */
export function foamReflectanceAt(absorption: number): number {
  return FOAM_VISIBLE_REFLECTANCE * Math.exp(-absorption * FOAM_WATER_PATH);
}

/** Foam's reflectance at red, green and blue (650, 510, 475 nm): the foam material's albedo. */
export function foamReflectance(): [number, number, number] {
  return PURE_WATER_ABSORPTION.map(foamReflectanceAt) as [number, number, number];
}
