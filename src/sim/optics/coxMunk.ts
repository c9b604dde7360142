/**
 * The sea surface's slope statistics as Cox & Munk measured them from the sun's glitter
 * (Cox, C. & Munk, W. 1954, "Measurement of the roughness of the sea surface from photographs
 * of the sun's glitter", J. Opt. Soc. Am. 44(11), 838–850, eq. 11 / Fig. 4, clean surface):
 * the mean-square slope, summed over both horizontal directions,
 *   σ² = σ_u² + σ_c² = 0.003 + 5.12·10⁻³ U ± 0.004,
 * with U the wind speed 12.5 m above the sea (their anemometer's height), m/s.
 */
export const COX_MUNK_INTERCEPT = 0.003;
export const COX_MUNK_SLOPE = 5.12e-3;

/** Cox & Munk's total mean-square slope for a wind U₁₂.₅ (m/s) measured 12.5 m up. */
export function coxMunkSlopeVariance(windSpeed12_5: number): number {
  return COX_MUNK_INTERCEPT + COX_MUNK_SLOPE * Math.max(0, windSpeed12_5);
}

/** Drag coefficient of the sea surface and von Kármán's constant, for the log wind profile. */
export const DRAG_COEFFICIENT = 1.3e-3;
export const VON_KARMAN = 0.4;

/**
 * U₁₂.₅ from U₁₀ by the neutral logarithmic profile U(z) = (u_* / κ) ln(z/z₀) with u_* = √C_D U₁₀:
 * U(z) = U₁₀ (1 + (√C_D / κ) ln(z / 10 m)). With C_D = 1.3·10⁻³ and κ = 0.4 (Stewart,
 * "Introduction to Physical Oceanography" 2008, §4.3), U₁₂.₅ = 1.0201 U₁₀.
 */
export function windAtHeight(windSpeed10: number, height: number): number {
  return windSpeed10 * (1 + (Math.sqrt(DRAG_COEFFICIENT) / VON_KARMAN) * Math.log(height / 10));
}

/** Cox & Munk's σ² for a wind given, as everywhere in the app, 10 m up. */
export function seaSlopeVariance(windSpeed10: number): number {
  return coxMunkSlopeVariance(windAtHeight(windSpeed10, 12.5));
}
