import FFT from 'fft.js';

/**
 * In-place 2-D inverse DFT without normalisation, f(x_p, z_q) = Σ_ab F_ab e^{+2πi(a p + b q)/n},
 * on an n × n interleaved complex array (index b·n + a ↔ row b = z, column a = x). Rows then
 * columns with fft.js (a radix-4 FFT; its inverseTransform divides by n, which we undo).
 */
export class InverseFft2d {
  private readonly fft: FFT;
  private readonly line: number[];
  private readonly result: number[];

  constructor(readonly n: number) {
    this.fft = new FFT(n);
    this.line = this.fft.createComplexArray() as number[];
    this.result = this.fft.createComplexArray() as number[];
  }

  transform(data: Float64Array): void {
    const { n, line, result, fft } = this;
    for (let b = 0; b < n; b++) {
      const o = 2 * b * n;
      for (let a = 0; a < 2 * n; a++) line[a] = data[o + a];
      fft.inverseTransform(result, line);
      for (let a = 0; a < 2 * n; a++) data[o + a] = result[a] * n;
    }
    for (let a = 0; a < n; a++) {
      for (let b = 0; b < n; b++) {
        line[2 * b] = data[2 * (b * n + a)];
        line[2 * b + 1] = data[2 * (b * n + a) + 1];
      }
      fft.inverseTransform(result, line);
      for (let b = 0; b < n; b++) {
        data[2 * (b * n + a)] = result[2 * b] * n;
        data[2 * (b * n + a) + 1] = result[2 * b + 1] * n;
      }
    }
  }
}
