/**
 * Test-only wind spectra, written here so the Gerstner and physics-estimator tests run
 * before the FFT model's spectra land in src/sim/ (branch fftsim). They are deliberately
 * not in src/: the app must have one copy of each formula. Replace with imports from the
 * FFT model's module once merged.
 */
export const G = 9.81;

/**
 * Pierson–Moskowitz (Pierson & Moskowitz 1964; Stewart, Introduction to Physical
 * Oceanography, eqs. 16.29–16.33): S(ω) = α g² ω⁻⁵ exp(−β (ω₀/ω)⁴), α = 8.1e-3, β = 0.74,
 * ω₀ = g / U₁₉.₅, so ωp = 0.877 g / U₁₉.₅ and Hs ≈ 0.21 U₁₉.₅² / g. U₁₉.₅ ≈ 1.026 U₁₀.
 */
export function piersonMoskowitz(u10: number): { spectrum: (omega: number) => number; peak: number; hs: number } {
  const u195 = 1.026 * u10;
  const omega0 = G / u195;
  return {
    spectrum: (w) => (w > 0 ? ((8.1e-3 * G * G) / w ** 5) * Math.exp(-0.74 * (omega0 / w) ** 4) : 0),
    peak: 0.877 * omega0,
    hs: (0.21 * u195 * u195) / G,
  };
}

/**
 * JONSWAP (Hasselmann et al. 1973): PM's shape with α = 0.076 (U₁₀² / (F g))^0.22,
 * ωp = 22 (g² / (U₁₀ F))^(1/3), times the peak enhancement γ^r, γ = 3.3,
 * r = exp(−(ω − ωp)² / (2 σ² ωp²)), σ = 0.07 below ωp and 0.09 above.
 */
export function jonswap(u10: number, fetch: number): { spectrum: (omega: number) => number; peak: number } {
  const alpha = 0.076 * ((u10 * u10) / (fetch * G)) ** 0.22;
  const peak = 22 * ((G * G) / (u10 * fetch)) ** (1 / 3);
  return {
    spectrum: (w) => {
      if (!(w > 0)) return 0;
      const sigma = w <= peak ? 0.07 : 0.09;
      const r = Math.exp(-((w - peak) ** 2) / (2 * sigma * sigma * peak * peak));
      return ((alpha * G * G) / w ** 5) * Math.exp(-1.25 * (peak / w) ** 4) * 3.3 ** r;
    },
    peak,
  };
}

/** cos² spreading about the wind, normalised: D(θ) = (2/π) cos² θ for |θ| < π/2. */
export function cosineSquared(theta: number): number {
  return Math.abs(theta) < Math.PI / 2 ? (2 / Math.PI) * Math.cos(theta) ** 2 : 0;
}
