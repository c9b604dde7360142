import { SUN_DISC_SLOPE_VARIANCE } from './sunDisc';
import { GRAVITY } from '../waves/dispersion';
import type { Cascade } from '../waves/fft/cascades';
import { PM_ALPHA, PM_BETA, windAt19_5 } from '../waves/spectra/piersonMoskowitz';

/**
 * How much of the sea's slope a picture shows, and how much must become roughness
 * (Bruneton, Neyret & Holzschuch 2010, "Real-time realistic ocean lighting using seamless
 * transitions from geometry to BRDF", Computer Graphics Forum 29(2), §4): the mean-square
 * slope of the waves the normals resolve, subtracted from the sea's total (Cox & Munk), is
 * the variance of the facets inside a pixel, which the glint integrates over.
 */

/**
 * Mean-square slope of a deep-water one-sided frequency spectrum S(ω) over the waves longer
 * than 2π/kCut: ∫₀^kCut k² S(k) dk with S(k) = S(ω) dω/dk, ω = √(g k) (so k² S(k) dk =
 * (ω⁴/g²) S(ω) dω). Integrated numerically in ln ω (the slope spectrum is broad and flat there).
 */
export function slopeVarianceUpTo(density: (omega: number) => number, kCut: number, steps = 4000): number {
  const omegaCut = Math.sqrt(GRAVITY * kCut);
  const lowest = Math.log(omegaCut) - 30;
  const h = (Math.log(omegaCut) - lowest) / steps;
  let sum = 0;
  for (let i = 0; i <= steps; i++) {
    const omega = Math.exp(lowest + i * h);
    const f = (omega ** 5 / GRAVITY ** 2) * density(omega);
    sum += (i === 0 || i === steps ? 0.5 : 1) * f;
  }
  return sum * h;
}

/** The exponential integral E₁(x) = ∫ₓ^∞ e⁻ᵗ/t dt (Abramowitz & Stegun 5.1.11 series; 5.1.22 continued fraction for x > 1). */
export function exponentialIntegral(x: number): number {
  if (x <= 1) {
    let sum = 0;
    let term = 1;
    for (let n = 1; n < 60; n++) {
      term *= -x / n;
      sum -= term / n;
    }
    return -0.5772156649015329 - Math.log(x) + sum;
  }
  // Lentz's continued fraction for e^x E₁(x) = 1/(x + 1 − 1²/(x + 3 − 2²/(x + 5 − …))).
  let b = x + 1;
  let c = 1e300;
  let d = 1 / b;
  let result = d;
  for (let n = 1; n < 200; n++) {
    const a = -n * n;
    b += 2;
    d = 1 / (a * d + b);
    c = b + a / c;
    const delta = c * d;
    result *= delta;
    if (Math.abs(delta - 1) < 1e-15) break;
  }
  return result * Math.exp(-x);
}

/**
 * The same for Pierson–Moskowitz in closed form: in deep water S(k) = (α/2) k⁻³ e^{−β (k₀/k)²},
 * k₀ = g/U₁₉.₅², so ∫₀^K k² S dk = (α/4) E₁(β k₀²/K²) ≈ (α/4) (ln(K²/(β k₀²)) − γ): α/2 of
 * mean-square slope per e-fold of wavenumber, the "equal slope per octave" of a k⁻³ tail.
 */
export function piersonMoskowitzSlopeVarianceUpTo(windSpeed10: number, kCut: number): number {
  const k0 = GRAVITY / windAt19_5(windSpeed10) ** 2;
  return (PM_ALPHA / 4) * exponentialIntegral((PM_BETA * k0 * k0) / (kCut * kCut));
}

/**
 * The share of a band's slope variance that a pixel of footprint `footprint` (m) still shows,
 * for a band of wavelengths [shortest, longest] whose slope variance is spread evenly over
 * ln k, as a k⁻³ tail spreads it (above): a wave is resolved while two samples fit in it
 * (λ ≥ 2 × footprint, Nyquist), so the share is the part of the band's ln-range longer than that.
 */
export function resolvedShare(footprint: number, shortest: number, longest: number): number {
  const share = Math.log(longest / (2 * footprint)) / Math.log(longest / shortest);
  return Math.min(1, Math.max(0, share));
}

/** The facets' variance within a pixel: the sea's total less what the normals show, never below the sun's disc. */
export { SUN_DISC_SLOPE_VARIANCE };

export function unresolvedSlopeVariance(total: number, resolved: number): number {
  return Math.max(SUN_DISC_SLOPE_VARIANCE, total - resolved);
}

/**
 * The shortest and longest wavelength (m) an FFT cascade carries: its band's edges
 * (src/sim/waves/fft/cascades.ts); the smallest tile runs to its grid's Nyquist, two texels,
 * and the largest from its own size.
 */
export function cascadeWavelengths(cascade: Cascade, n: number): { shortest: number; longest: number } {
  const shortest = Number.isFinite(cascade.kMax) ? (2 * Math.PI) / cascade.kMax : (2 * cascade.size) / n;
  const longest = cascade.kMin > 0 ? (2 * Math.PI) / cascade.kMin : cascade.size;
  return { shortest, longest };
}
