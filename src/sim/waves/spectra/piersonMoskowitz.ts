import { GRAVITY } from '../dispersion';

/**
 * Pierson–Moskowitz spectrum of a fully developed sea (Pierson & Moskowitz 1964, J. Geophys.
 * Res. 69(24), eq. 1): S(ω) = α g² ω⁻⁵ exp(−β (ω₀/ω)⁴), with α = 8.1·10⁻³, β = 0.74 and
 * ω₀ = g / U19.5, U19.5 being the wind speed 19.5 m above the sea. S is the one-sided
 * frequency spectrum of surface elevation, m²·s/rad.
 */
export const PM_ALPHA = 8.1e-3;
export const PM_BETA = 0.74;

/**
 * U19.5 from U10 with the logarithmic wind profile: U19.5 ≈ 1.026 U10 (Stewart,
 * "Introduction to Physical Oceanography" (2008), §16.3, for a drag coefficient 1.3·10⁻³).
 */
export function windAt19_5(windSpeed10: number): number {
  return 1.026 * windSpeed10;
}

export function piersonMoskowitz(omega: number, windSpeed10: number): number {
  if (omega <= 0) return 0;
  const omega0 = GRAVITY / windAt19_5(windSpeed10);
  const r = omega0 / omega;
  return ((PM_ALPHA * GRAVITY * GRAVITY) / omega ** 5) * Math.exp(-PM_BETA * r ** 4);
}

/** Peak frequency: dS/dω = 0 gives ωp = (4β/5)^¼ g/U19.5 ≈ 0.877 g/U19.5. */
export function piersonMoskowitzPeak(windSpeed10: number): number {
  return ((4 * PM_BETA) / 5) ** 0.25 * (GRAVITY / windAt19_5(windSpeed10));
}

/**
 * m₀ = ∫S dω in closed form: with u = ω⁻⁴, ∫ α g² ω⁻⁵ e^{−β ω₀⁴ ω⁻⁴} dω = α g² / (4 β ω₀⁴)
 * = α U19.5⁴ / (4 β g²). Then Hs = 4√m₀ = 2 √(α/β) U19.5²/g = 0.209 U19.5²/g, the "0.21" of
 * Pierson & Moskowitz.
 */
export function piersonMoskowitzM0(windSpeed10: number): number {
  const u = windAt19_5(windSpeed10);
  return (PM_ALPHA * u ** 4) / (4 * PM_BETA * GRAVITY * GRAVITY);
}
