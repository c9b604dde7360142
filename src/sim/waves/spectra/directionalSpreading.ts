import { GRAVITY } from '../dispersion';

/**
 * Directional spreading: how a wind sea's energy at one frequency spreads around the wind
 * direction. The cos-2s model of Longuet-Higgins, Cartwright & Smith (1963), "Observations of
 * the directional spectrum of sea waves using the motions of a floating buoy":
 *   D(θ) = N(s) cos^{2s}(θ/2),  N(s) = Γ(s+1) / (2 √π Γ(s+½)),
 * θ the angle from the wind in (−π, π]; N makes ∫D dθ = 1 so spreading moves energy between
 * directions without adding any. s ≈ 5–10 near the peak of a wind sea (Mitsuyasu et al. 1975).
 */
export function cos2sSpreading(theta: number, s: number): number {
  const c = Math.cos(theta / 2);
  return cos2sNormalisation(s) * Math.abs(c) ** (2 * s);
}

export function cos2sNormalisation(s: number): number {
  return Math.exp(logGamma(s + 1) - logGamma(s + 0.5)) / (2 * Math.sqrt(Math.PI));
}

/** ln Γ(x) for x > 0 by the Lanczos approximation (g = 7, n = 9; Numerical Recipes 3rd ed. §6.1), ~1e-15 relative. */
export function logGamma(x: number): number {
  const c = [
    0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313, -176.61502916214059, 12.507343278686905,
    -0.13857109526572012, 9.9843695780195716e-6, 1.5056327351493116e-7,
  ];
  if (x < 0.5) return Math.log(Math.PI / Math.abs(Math.sin(Math.PI * x))) - logGamma(1 - x);
  const z = x - 1;
  let a = c[0];
  const t = z + 7.5;
  for (let i = 1; i < 9; i++) a += c[i] / (z + i);
  return 0.5 * Math.log(2 * Math.PI) + (z + 0.5) * Math.log(t) - t + Math.log(a);
}

/**
 * The cos-2s exponent as it was measured during JONSWAP, varying with frequency: Hasselmann,
 * Dunckel & Ewing (1980), "Directional wave spectra observed during JONSWAP 1973", J. Phys.
 * Oceanogr. 10, 1264–1280, eq. 41:
 *   s = 6.97 (ω/ωp)^4.06                          for ω < 1.05 ωp,
 *   s = 9.77 (ω/ωp)^μ,  μ = −2.33 − 1.45 (U ωp/g − 1.17)   for ω ≥ 1.05 ωp,
 * U ωp / g = U / c_p the wave age's inverse. Narrowest (s ≈ 9) just above the peak, wider for
 * the longer and the shorter waves. (Also in Horvath 2015, "Empirical directional wave spectra
 * for computer graphics", §5.3.)
 */
export function hasselmannSpreadingExponent(omega: number, omegaPeak: number, windSpeed: number): number {
  const r = omega / omegaPeak;
  if (r < 1.05) return 6.97 * r ** 4.06;
  const mu = -2.33 - 1.45 * ((windSpeed * omegaPeak) / GRAVITY - 1.17);
  return 9.77 * r ** mu;
}

/** Which spreading the spectral sea uses: cos-2s with the user's s, or Hasselmann's s(ω). */
export type SpreadingModel = 'cos-2s' | 'hasselmann';

/**
 * D(θ, ω) for a sea: cos-2s with exponent `s` at every frequency, or Hasselmann et al.'s
 * exponent for each ω relative to the peak ωp at wind speed U (then `s` is not read).
 */
export function spreadingFunction(
  model: SpreadingModel,
  s: number,
  omegaPeak: number,
  windSpeed: number,
): (theta: number, omega: number) => number {
  return model === 'hasselmann'
    ? (theta, omega) => hasselmannSpreading(theta, omega, omegaPeak, windSpeed)
    : (theta) => cos2sSpreading(theta, s);
}

/** Hasselmann et al. (1980) spreading: cos-2s with the exponent of its frequency (above); ∫D dθ = 1 at every ω. */
export function hasselmannSpreading(theta: number, omega: number, omegaPeak: number, windSpeed: number): number {
  return cos2sSpreading(theta, hasselmannSpreadingExponent(omega, omegaPeak, windSpeed));
}
