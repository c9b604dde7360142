import { GRAVITY } from '../dispersion';

/**
 * The Phillips spectrum as Tessendorf uses it ("Simulating Ocean Water", 2001, §3.3, eq. 24):
 * P(k) ∝ exp(−1/(k L)²) / k⁴ with L = U²/g, the largest wave a wind U raises. Written as a
 * one-sided frequency spectrum with the deep-water map k = ω²/g (S(ω) = S(k) dk/dω with
 * S(k) ∝ k·P(k)), it is Phillips' (1958) saturation range α g² ω⁻⁵ with a low-frequency cut:
 *   S(ω) = α g² ω⁻⁵ exp(−(g/(U ω))⁴),  α = 8.1·10⁻³ (Phillips' constant, as in PM).
 * Tessendorf's free amplitude A is thus fixed by Phillips' constant; his |k̂·ŵ|² direction
 * factor is replaced by the shared spreading function.
 */
export const PHILLIPS_ALPHA = 8.1e-3;

export function phillips(omega: number, windSpeed: number): number {
  if (omega <= 0) return 0;
  const cut = GRAVITY / (windSpeed * omega);
  return ((PHILLIPS_ALPHA * GRAVITY * GRAVITY) / omega ** 5) * Math.exp(-(cut ** 4));
}

/** dS/dω = 0: −5/ω + 4 (g/U)⁴ ω⁻⁵ = 0, so ωp = (4/5)^¼ g/U. */
export function phillipsPeak(windSpeed: number): number {
  return 0.8 ** 0.25 * (GRAVITY / windSpeed);
}

/** m₀ = α g² / (4 (g/U)⁴) = α U⁴ / (4 g²), the same integral as Pierson–Moskowitz with β = 1. */
export function phillipsM0(windSpeed: number): number {
  return (PHILLIPS_ALPHA * windSpeed ** 4) / (4 * GRAVITY * GRAVITY);
}
