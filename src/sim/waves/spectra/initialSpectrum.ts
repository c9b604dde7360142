import { angularFrequency, quantiseFrequency } from '../dispersion';
import { inBand, type Cascade } from '../fft/cascades';
import { gaussianRandom } from '../../noise/gaussianRandom';

/**
 * h₀(k), the sea's random initial Fourier amplitudes, drawn once from the seed (Tessendorf
 * 2001, §3.4, eq. 25): h₀(k) = (ξr + i ξi)/√2 · √(P(k)) with ξ standard normal, and here
 * P(k) = ½ F(k) Δk². The ½ is because mode k appears twice in the height field, as
 * h₀(k) e^{iωt} and as conj(h₀(−k)) e^{−iωt}: E|h̃(k)|² summed over all k is then ∫∫F = m₀.
 *
 * Grid convention (shared with the GPU): an n × n tile of side L; mode (a, b), stored at
 * index b·n + a, has signed indices a', b' ∈ [−n/2, n/2) and wavevector (a', b')·2π/L.
 * The Nyquist row and column (a' or b' = −n/2) and k = 0 are left empty: −k of a Nyquist
 * mode is itself, which would make the choppy displacement −i k̂ h complex.
 */
export interface SpectralTile {
  cascade: Cascade;
  n: number;
  /** h₀, interleaved re, im, n·n complex values. */
  h0: Float64Array;
  /** ω(|k|), quantised to multiples of 2π/T, per mode, rad/s. */
  omega: Float64Array;
}

/** Repeat period T of the quantised dispersion (s): every sea repeats exactly after T. */
export const REPEAT_PERIOD = 1000;

export function signedIndex(a: number, n: number): number {
  return a < n / 2 ? a : a - n;
}

export function initialSpectrum(
  cascade: Cascade,
  n: number,
  spectrum: (kx: number, kz: number) => number,
  depth: number,
  seed: number,
  stream: number,
): SpectralTile {
  const dk = (2 * Math.PI) / cascade.size;
  const h0 = new Float64Array(2 * n * n);
  const omega = new Float64Array(n * n);
  const gauss = gaussianRandom(seed, stream);
  for (let b = 0; b < n; b++) {
    for (let a = 0; a < n; a++) {
      // Always draw both numbers, so the value of one mode never depends on which others are cut.
      const xr = gauss();
      const xi = gauss();
      const as = signedIndex(a, n);
      const bs = signedIndex(b, n);
      const kx = as * dk;
      const kz = bs * dk;
      const k = Math.hypot(kx, kz);
      const i = b * n + a;
      omega[i] = quantiseFrequency(angularFrequency(k, depth), REPEAT_PERIOD);
      if (k === 0 || as === -n / 2 || bs === -n / 2 || !inBand(cascade, k)) continue;
      const amplitude = Math.sqrt(0.5 * spectrum(kx, kz) * dk * dk);
      h0[2 * i] = (amplitude * xr) / Math.SQRT2;
      h0[2 * i + 1] = (amplitude * xi) / Math.SQRT2;
    }
  }
  return { cascade, n, h0, omega };
}
