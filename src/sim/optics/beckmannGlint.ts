/**
 * The sun's reflection on a rough sea: a microfacet BRDF whose facets' slopes are Gaussian
 * (Beckmann; Cox & Munk's measured distribution, to lowest order), as Bruneton, Neyret &
 * Holzschuch 2010 write it (§4.1, eq. 7–9, their reflectedSunRadiance):
 *
 *   L = E_sun F(v·h) p(ζ_h) / (4 cos θ_v cos⁴θ_h (1 + Λ(v) + Λ(l)))
 *
 * with h the half vector between the sun l and the eye v, ζ_h = tan θ_h its slope relative to
 * the mean normal, p the slope density of total mean-square slope σ² (σ²/2 per axis,
 * isotropic), and Λ Smith's shadowing of the Beckmann surface, in Walter et al.'s rational
 * form. shaders/ocean.frag evaluates the same expression; this twin is what the tests hold to
 * the published values.
 */

/** Isotropic Gaussian density of the slope vector ζ with total variance σ²: e^{−|ζ|²/σ²} / (π σ²). */
export function beckmannSlopeDensity(slopeSquared: number, variance: number): number {
  return Math.exp(-slopeSquared / variance) / (Math.PI * variance);
}

/** erfc(x) for x ≥ 0 (Abramowitz & Stegun 7.1.26, |error| < 1.5·10⁻⁷). */
export function complementaryErrorFunction(x: number): number {
  const t = 1 / (1 + 0.3275911 * x);
  const poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  return poly * Math.exp(-x * x);
}

/**
 * Smith's Λ for a Beckmann surface seen at cos θ, with slope variance σ²_dir in the plane of
 * incidence (σ²/2 for an isotropic sea): ν = cot θ / √(2 σ²_dir),
 * Λ = (e^{−ν²} / (ν √π) − erfc ν) / 2 (Smith 1967; Bruneton et al. 2010 eq. 8).
 */
export function smithLambda(cosTheta: number, directionalVariance: number): number {
  const c = Math.min(Math.max(cosTheta, 1e-4), 0.999999);
  const nu = c / Math.sqrt((1 - c * c) * 2 * directionalVariance);
  return Math.max(0, (Math.exp(-nu * nu) / (nu * Math.sqrt(Math.PI)) - complementaryErrorFunction(nu)) / 2);
}

/**
 * Walter, Marschner, Li & Torrance 2007 ("Microfacet Models for Refraction through Rough
 * Surfaces", eq. 27): Smith's Beckmann shadowing as a rational function of the same ν,
 * Λ ≈ (1 − 1.259 ν + 0.396 ν²) / (3.535 ν + 2.181 ν²) below ν = 1.6 and 0 above: the shadowing
 * factor 1 / (1 + Λ) is within 0.004 of smithLambda's (tests/unit/sim/optics/beckmannGlint.test.ts). The
 * glint uses it: no exponential and no erfc per pixel.
 */
export function smithLambdaRational(cosTheta: number, directionalVariance: number): number {
  const c = Math.min(Math.max(cosTheta, 1e-4), 0.999999);
  const nu = c / Math.sqrt((1 - c * c) * 2 * directionalVariance);
  return nu < 1.6 ? (1 - 1.259 * nu + 0.396 * nu * nu) / (3.535 * nu + 2.181 * nu * nu) : 0;
}

type Vec3 = readonly [number, number, number];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * Radiance of the sun reflected towards `view` (unit, surface to eye) by a sea of mean normal
 * `normal` and facet variance σ², per unit sun irradiance, without Fresnel (the caller
 * multiplies by F(v·h)): p(ζ_h) / (4 cos θ_v cos⁴θ_h (1 + Λ_v + Λ_l)).
 */
export function glintPerIrradiance(sun: Vec3, view: Vec3, normal: Vec3, variance: number): number {
  const sum: Vec3 = [sun[0] + view[0], sun[1] + view[1], sun[2] + view[2]];
  const length = Math.hypot(...sum);
  const half: Vec3 = [sum[0] / length, sum[1] / length, sum[2] / length];
  const zH = dot(half, normal);
  const zV = Math.max(dot(view, normal), 0.01);
  const zL = Math.max(dot(sun, normal), 0.01);
  if (zH <= 0) return 0;
  const slopeSquared = (1 - zH * zH) / (zH * zH);
  const shadowing = 1 + smithLambdaRational(zV, variance / 2) + smithLambdaRational(zL, variance / 2);
  return beckmannSlopeDensity(slopeSquared, variance) / (4 * zV * zH ** 4 * shadowing);
}
