import FFT from 'fft.js';
import { describe, expect, it } from 'vitest';
import { stockhamInverse, stockhamStage } from '../../src/sim/stockhamFft';
import { seededRandom } from '../../src/sim/integerHash';

describe('Stockham radix-2 inverse FFT (the GPU pass’s indexing)', () => {
  for (const n of [8, 64, 256]) {
    it(`equals fft.js's inverse transform ×n for n = ${n}`, () => {
      const random = seededRandom(n);
      const input = Float64Array.from({ length: 2 * n }, () => random() - 0.5);
      const fft = new FFT(n);
      const expected = fft.createComplexArray() as number[];
      fft.inverseTransform(expected, Array.from(input));
      const got = stockhamInverse(input, n);
      for (let i = 0; i < 2 * n; i++) expect(got[i]).toBeCloseTo(expected[i] * n, 10);
    });
  }
  it('negative control: a stage with the twiddle conjugated (a forward stage) does not give the inverse', () => {
    const n = 16;
    const input = new Float64Array(2 * n);
    input[2 * 3] = 1; // one mode e^{2πi·3·o/n}
    let data = input;
    for (let half = 1; half < n; half *= 2) {
      const conj = (a: Float64Array) => a.map((v, i) => (i % 2 ? -v : v));
      data = conj(stockhamStage(conj(data), n, half));
    }
    const good = stockhamInverse(input, n);
    expect(good[2 * 1 + 1]).toBeCloseTo(Math.sin((2 * Math.PI * 3) / n), 12);
    expect(Math.abs(data[2 * 1 + 1] - good[2 * 1 + 1])).toBeGreaterThan(0.5);
  });
});
