/**
 * How much of the sea is white: whitecap coverage against wind speed, W = 3.84·10⁻⁶ U₁₀^3.41
 * (Monahan & O'Muircheartaigh 1980, J. Phys. Oceanogr. 10, 2094), as a fraction: about 1 % at
 * 10 m/s, 4 % at 15 m/s, 10 % at 20 m/s, nothing to see at 4 m/s.
 */
export function whitecapCoverage(windSpeed: number): number {
  return Math.min(1, 3.84e-6 * Math.pow(windSpeed, 3.41));
}

/**
 * The standard normal quantile z with P(Z > z) = p, for 0 < p ≤ 0.5 (Abramowitz & Stegun
 * 26.2.23, |error| < 4.5·10⁻⁴).
 */
export function upperNormalQuantile(p: number): number {
  const t = Math.sqrt(-2 * Math.log(p));
  return t - (2.515517 + 0.802853 * t + 0.010328 * t * t) / (1 + 1.432788 * t + 0.189269 * t * t + 0.001308 * t * t * t);
}

/**
 * Foam left behind decays: whitecap patches fade with an e-folding time τ of 0.5–8 s, longer
 * for larger breakers (Callaghan, A. H., Deane, G. B. & Stokes, M. D. 2012, "Two regimes of
 * laboratory whitecap foam decay", J. Geophys. Res. 117, C09015); 2.5 s is a mid-sized one,
 * the default of the `foamFade` parameter.
 */
export const FOAM_FADE_SECONDS = 2.5;

/**
 * The share of foam still there `elapsed` simulation seconds later, e^{−t/τ}: a function of
 * time, never of frames, so that stepping and playing leave the same foam.
 */
export function foamRemaining(elapsed: number, fadeSeconds = FOAM_FADE_SECONDS): number {
  return Math.exp(-elapsed / fadeSeconds);
}
