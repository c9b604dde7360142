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
 * Spread of the Jacobian J of the choppy map per unit choppiness λ. The cascades carry the
 * same range of wavelengths relative to the peak at every wind, so J's spread does not grow
 * with the wind by itself (measured over 20 000 points, seed 1, λ = 1: 10 % quantile 0.84 and
 * 1 % quantile 0.72 at U = 10, 15 and 20 m/s alike, a near-Gaussian spread of 0.125).
 */
export const JACOBIAN_SPREAD = 0.125;

/**
 * The Jacobian below which the sea foams, chosen so that the share of the sea below it is
 * Monahan's coverage for this wind (J taken as Gaussian about 1 with spread 0.125 λ), plus a
 * user's bias (the `foamThreshold` parameter): more foam as the wind rises, as observed.
 */
export function foamJacobianThreshold(windSpeed: number, choppiness: number, bias = 0): number {
  const coverage = Math.min(0.5, Math.max(1e-9, whitecapCoverage(windSpeed)));
  return 1 - JACOBIAN_SPREAD * choppiness * upperNormalQuantile(coverage) + bias;
}

/**
 * The same threshold for a field whose Jacobian has spread `jacobianSpread` (one cascade's
 * band: λ times its RMS slope, src/sim/waves/spectra/spectralBounds.ts), so that each cascade's share of
 * folding crests is Monahan's coverage at the scale of its own waves. Measured (U = 10–20 m/s,
 * 128², seed 1): the three cascades' J spreads are 0.063, 0.079 and 0.095 λ, which the RMS
 * slopes give exactly. `share` takes that part of the coverage only.
 */
export function foamThresholdForSpread(jacobianSpread: number, windSpeed: number, bias = 0, share = 1): number {
  const coverage = Math.min(0.5, Math.max(1e-9, share * whitecapCoverage(windSpeed)));
  return 1 - jacobianSpread * upperNormalQuantile(coverage) + bias;
}

/**
 * Foam left behind decays: whitecap patches fade with an e-folding time τ of 0.5–8 s, longer
 * for larger breakers (Callaghan, A. H., Deane, G. B. & Stokes, M. D. 2012, "Two regimes of
 * laboratory whitecap foam decay", J. Geophys. Res. 117, C09015); 2.5 s is a mid-sized one.
 */
export const FOAM_FADE_SECONDS = 2.5;

/**
 * The share of foam still there `elapsed` simulation seconds later, e^{−t/τ}: a function of
 * time, never of frames, so that stepping and playing leave the same foam.
 */
export function foamRemaining(elapsed: number, fadeSeconds = FOAM_FADE_SECONDS): number {
  return Math.exp(-elapsed / fadeSeconds);
}
