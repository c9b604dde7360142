import type { SpectralTile } from '../spectra/initialSpectrum';
import { signedIndex } from '../spectra/initialSpectrum';

/**
 * The eight real fields a cascade needs each frame, built in frequency space at time τ and
 * packed two real fields per complex spectrum (a real field's spectrum X plus i times another's
 * Y transforms to x + i y, so one complex FFT yields both; Press et al., Numerical Recipes §12.3):
 *   spectra[0] = Dx + i·h      → after the FFT: (dx, dy)
 *   spectra[1] = Dz + i·∂xDx   →                (dz, ∂dx/∂x)
 *   spectra[2] = ∂xh + i·∂zh   →                (∂h/∂x, ∂h/∂z)
 *   spectra[3] = ∂zDz + i·∂xDz →                (∂dz/∂z, ∂dx/∂z)
 * Time evolution (Tessendorf 2001 eq. 26): h̃(k,t) = h₀(k) e^{iωt} + conj(h₀(−k)) e^{−iωt},
 * which is Hermitian, h̃(−k) = conj(h̃(k)), so every field is real.
 * Choppy displacement: D̃ = i λ (k/|k|) h̃. Tessendorf (eq. 29) writes −i k̂ h̃ for x + λD; we add
 * D with the opposite sign, which is the one that pulls points towards the crests (for h = cos kx,
 * dx = −λ sin kx: Gerstner's trochoid), checked by a unit test. Exact slopes: ∂h/∂x ↔ i kx h̃.
 * Derivatives of D for the Jacobian J = (1 + ∂xDx)(1 + ∂zDz) − ∂xDz², where J < 1 compresses and
 * J < 0 folds (foam; Tessendorf §4.3): ∂xDx ↔ −λ kx²/k h̃, ∂zDz ↔ −λ kz²/k h̃, ∂xDz ↔ −λ kx kz/k h̃.
 */
export function evolveSpectra(tile: SpectralTile, tau: number, choppiness: number, out?: Float64Array[]): Float64Array[] {
  const { n, h0, omega } = tile;
  const dk = (2 * Math.PI) / tile.cascade.size;
  const spectra = out ?? [0, 1, 2, 3].map(() => new Float64Array(2 * n * n));
  const [s0, s1, s2, s3] = spectra;
  const lambda = choppiness;
  for (let b = 0; b < n; b++) {
    const bm = (n - b) % n;
    const kz = signedIndex(b, n) * dk;
    for (let a = 0; a < n; a++) {
      const am = (n - a) % n;
      const kx = signedIndex(a, n) * dk;
      const i = b * n + a;
      const j = bm * n + am;
      const phase = omega[i] * tau;
      const c = Math.cos(phase);
      const s = Math.sin(phase);
      // h₀(k) e^{iφ} + conj(h₀(−k)) e^{−iφ}; ω(−k) = ω(k).
      const ar = h0[2 * i];
      const ai = h0[2 * i + 1];
      const br = h0[2 * j];
      const bi = -h0[2 * j + 1];
      const hr = ar * c - ai * s + (br * c + bi * s);
      const hi = ar * s + ai * c + (bi * c - br * s);
      const k = Math.hypot(kx, kz);
      const ux = k > 0 ? kx / k : 0;
      const uz = k > 0 ? kz / k : 0;
      // i·u·h = u·(−hi + i hr)
      const dxr = -lambda * ux * hi;
      const dxi = lambda * ux * hr;
      const dzr = -lambda * uz * hi;
      const dzi = lambda * uz * hr;
      const fxx = -lambda * kx * ux;
      const fzz = -lambda * kz * uz;
      const fxz = -lambda * kx * uz;
      // spectra[0] = Dx + i h
      s0[2 * i] = dxr - hi;
      s0[2 * i + 1] = dxi + hr;
      // spectra[1] = Dz + i (fxx h)
      s1[2 * i] = dzr - fxx * hi;
      s1[2 * i + 1] = dzi + fxx * hr;
      // spectra[2] = (i kx h) + i (i kz h) = (−kx hi − kz hr) + i (kx hr − kz hi)
      s2[2 * i] = -kx * hi - kz * hr;
      s2[2 * i + 1] = kx * hr - kz * hi;
      // spectra[3] = fzz h + i fxz h
      s3[2 * i] = fzz * hr - fxz * hi;
      s3[2 * i + 1] = fzz * hi + fxz * hr;
    }
  }
  return spectra;
}
