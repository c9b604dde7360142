/**
 * The radix-2 Stockham FFT exactly as the GPU runs it, one output value per fragment: stage
 * s (half-size Ns = 2^s) reads two inputs and writes output o as
 *   k = o mod Ns,  j = ⌊o / 2Ns⌋·Ns + k,  r = ⌊o / Ns⌋ mod 2,
 *   out[o] = in[j] + (−1)^r · e^{+iπk/Ns} · in[j + n/2].
 * After log₂n stages the result is the unnormalised inverse DFT Σ in[a] e^{+2πi a o/n}, in
 * natural order: Stockham's autosort form needs no bit reversal, which suits a pass that can
 * only write its own texel (Govindaraju et al., "High performance discrete Fourier transforms
 * on graphics processors", SC 2008, fig. 2; Van Loan, "Computational Frameworks for the FFT",
 * 1992, §1.7). The twiddle e^{iπk/Ns} is read from a table of e^{2πi m/n}, m = k·n/(2Ns).
 */
export function stockhamSource(o: number, n: number, halfSize: number): { j: number; r: number; twiddle: number } {
  const k = o % halfSize;
  return { j: Math.floor(o / (2 * halfSize)) * halfSize + k, r: Math.floor(o / halfSize) % 2, twiddle: (k * n) / (2 * halfSize) };
}

/** One stage on an interleaved complex array (the CPU mirror of shaders/fftStage.frag). */
export function stockhamStage(input: Float64Array, n: number, halfSize: number): Float64Array {
  const out = new Float64Array(2 * n);
  for (let o = 0; o < n; o++) {
    const { j, r, twiddle } = stockhamSource(o, n, halfSize);
    const angle = (2 * Math.PI * twiddle) / n;
    const wr = Math.cos(angle);
    const wi = Math.sin(angle);
    const br = input[2 * (j + n / 2)];
    const bi = input[2 * (j + n / 2) + 1];
    const sign = r === 0 ? 1 : -1;
    out[2 * o] = input[2 * j] + sign * (wr * br - wi * bi);
    out[2 * o + 1] = input[2 * j + 1] + sign * (wr * bi + wi * br);
  }
  return out;
}

/** The whole 1-D inverse DFT by log₂n Stockham stages. */
export function stockhamInverse(input: Float64Array, n: number): Float64Array {
  let data = input;
  for (let half = 1; half < n; half *= 2) data = stockhamStage(data, n, half);
  return data;
}
