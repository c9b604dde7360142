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
