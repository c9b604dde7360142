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

/**
 * The radices of the stages of one n-point transform as the GPU runs them: radix 4 wherever it
 * fits (one radix-4 pass does the work of two radix-2 passes: half the passes and half the
 * render-target writes), and one radix-2 stage first when log₂n is odd. 128 → [2, 4, 4, 4].
 */
export function stockhamRadices(n: number): number[] {
  const log2 = Math.log2(n);
  if (!Number.isInteger(log2) || log2 < 1) throw new RangeError(`n must be a power of two ≥ 2, got ${n}.`);
  return [...(log2 % 2 === 1 ? [2] : []), ...new Array<number>(Math.floor(log2 / 2)).fill(4)];
}

/**
 * One mixed-radix Stockham stage of radix R with Ns the product of the radices before it
 * (Govindaraju et al. 2008): output o takes k = o mod Ns, j = ⌊o/(R·Ns)⌋·Ns + k,
 * r = ⌊o/Ns⌋ mod R, and out[o] = Σ_{m<R} e^{2πi·m·r/R} · e^{2πi·m·k/(R·Ns)} · in[j + m·n/R].
 * With R = 2 it is stockhamStage. The CPU mirror of shaders/fftStage.frag (RADIX_4 or not).
 */
export function stockhamRadixStage(input: Float64Array, n: number, halfSize: number, radix: number): Float64Array {
  const out = new Float64Array(2 * n);
  for (let o = 0; o < n; o++) {
    const k = o % halfSize;
    const j = Math.floor(o / (radix * halfSize)) * halfSize + k;
    const r = Math.floor(o / halfSize) % radix;
    let re = 0;
    let im = 0;
    for (let m = 0; m < radix; m++) {
      // The twiddle e^{2πi·q/n} of the table (q = m·k·n/(R·Ns) < n), then the DFT's e^{2πi·m·r/R}.
      const angle = (2 * Math.PI * ((m * k * n) / (radix * halfSize))) / n + (2 * Math.PI * m * r) / radix;
      const ar = input[2 * (j + (m * n) / radix)];
      const ai = input[2 * (j + (m * n) / radix) + 1];
      re += Math.cos(angle) * ar - Math.sin(angle) * ai;
      im += Math.cos(angle) * ai + Math.sin(angle) * ar;
    }
    out[2 * o] = re;
    out[2 * o + 1] = im;
  }
  return out;
}

/** The whole 1-D inverse DFT by the stages of stockhamRadices(n), as the GPU runs it. */
export function stockhamMixedInverse(input: Float64Array, n: number, radices: readonly number[] = stockhamRadices(n)): Float64Array {
  let data = input;
  let halfSize = 1;
  for (const radix of radices) {
    data = stockhamRadixStage(data, n, halfSize, radix);
    halfSize *= radix;
  }
  return data;
}
