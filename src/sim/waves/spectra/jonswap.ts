import { GRAVITY } from '../dispersion';
import { piersonMoskowitzPeak } from './piersonMoskowitz';

/**
 * JONSWAP spectrum of a fetch-limited sea (Hasselmann et al. 1973, "Measurements of wind-wave
 * growth and swell decay during the Joint North Sea Wave Project", Dtsch. Hydrogr. Z. A8(12),
 * eq. 2.8 and fig. 2.13):
 *   S(ω) = α g² ω⁻⁵ exp(−5/4 (ωp/ω)⁴) γ^r,  r = exp(−(ω − ωp)² / (2 σ² ωp²)),
 * γ = 3.3, σ = 0.07 below the peak and 0.09 above, and from the dimensionless fetch
 * x̃ = g F / U10²: α = 0.076 x̃^−0.22 and ωp = 22 (g² / (U10 F))^⅓.
 */
export const JONSWAP_GAMMA = 3.3;
export const JONSWAP_SIGMA_BELOW = 0.07;
export const JONSWAP_SIGMA_ABOVE = 0.09;

export interface JonswapShape {
  alpha: number;
  peak: number;
}

/**
 * α and ωp from wind and fetch (m). A fetch long enough to give a peak below the fully
 * developed Pierson–Moskowitz one cannot grow the sea further, so ωp and α stop there (the
 * JONSWAP fit is for growing seas; Hasselmann et al. 1973 §2.5).
 */
export function jonswapShape(windSpeed10: number, fetch: number): JonswapShape {
  const fetchLimitedPeak = 22 * ((GRAVITY * GRAVITY) / (windSpeed10 * fetch)) ** (1 / 3);
  const developedPeak = piersonMoskowitzPeak(windSpeed10);
  if (fetchLimitedPeak >= developedPeak) {
    return { alpha: 0.076 * ((windSpeed10 * windSpeed10) / (fetch * GRAVITY)) ** 0.22, peak: fetchLimitedPeak };
  }
  // The fetch that gives ωp = developedPeak, and the α of that fetch.
  const developedFetch = (22 / developedPeak) ** 3 * ((GRAVITY * GRAVITY) / windSpeed10);
  return { alpha: 0.076 * ((windSpeed10 * windSpeed10) / (developedFetch * GRAVITY)) ** 0.22, peak: developedPeak };
}

export function jonswap(omega: number, windSpeed10: number, fetch: number, gamma = JONSWAP_GAMMA): number {
  if (omega <= 0) return 0;
  const { alpha, peak } = jonswapShape(windSpeed10, fetch);
  return jonswapWithShape(omega, alpha, peak, gamma);
}

export function jonswapWithShape(omega: number, alpha: number, peak: number, gamma = JONSWAP_GAMMA): number {
  if (omega <= 0) return 0;
  const sigma = omega <= peak ? JONSWAP_SIGMA_BELOW : JONSWAP_SIGMA_ABOVE;
  const r = Math.exp(-((omega - peak) ** 2) / (2 * sigma * sigma * peak * peak));
  return ((alpha * GRAVITY * GRAVITY) / omega ** 5) * Math.exp(-1.25 * (peak / omega) ** 4) * gamma ** r;
}

/**
 * m₀ of JONSWAP. For γ = 1 it is exact: α g² / (5 ωp⁴) (the Pierson–Moskowitz integral with
 * β ω₀⁴ = 5/4 ωp⁴). The peak enhancement multiplies it by about 1 / (1 − 0.287 ln γ)
 * (DNV-RP-C205 (2010) §3.5.5.2, stated accurate to a few per cent for 1 ≤ γ ≤ 7).
 */
export function jonswapM0Approx(alpha: number, peak: number, gamma = JONSWAP_GAMMA): number {
  return (alpha * GRAVITY * GRAVITY) / (5 * peak ** 4) / (1 - 0.287 * Math.log(gamma));
}
