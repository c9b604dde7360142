import FFT from 'fft.js';
import { describe, expect, it } from 'vitest';
import {
  stockhamInverse,
  stockhamMixedInverse,
  stockhamRadices,
  stockhamRadixStage,
  stockhamStage,
} from '../../../../../src/sim/waves/fft/stockhamFft';
import { seededRandom } from '../../../../../src/sim/noise/integerHash';

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

describe('mixed radix-4/radix-2 Stockham inverse FFT (the GPU passes since radix 4)', () => {
  it('plans radix 4 where it fits, one radix-2 stage first for odd log₂n', () => {
    expect(stockhamRadices(64)).toEqual([4, 4, 4]);
    expect(stockhamRadices(128)).toEqual([2, 4, 4, 4]);
    expect(stockhamRadices(256)).toEqual([4, 4, 4, 4]);
    expect(() => stockhamRadices(96)).toThrow(RangeError);
  });
  for (const n of [8, 64, 128, 256]) {
    it(`equals fft.js's inverse transform ×n for n = ${n} (${stockhamRadices(n).join(', ')})`, () => {
      const random = seededRandom(n + 17);
      const input = Float64Array.from({ length: 2 * n }, () => random() - 0.5);
      const fft = new FFT(n);
      const expected = fft.createComplexArray() as number[];
      fft.inverseTransform(expected, Array.from(input));
      const got = stockhamMixedInverse(input, n);
      for (let i = 0; i < 2 * n; i++) expect(got[i]).toBeCloseTo(expected[i] * n, 9);
      // its radix-2 stage is the radix-2 pass's own
      const two = stockhamRadixStage(input, n, 2, 2);
      const one = stockhamStage(input, n, 2);
      for (let i = 0; i < 2 * n; i++) expect(two[i]).toBeCloseTo(one[i], 12);
    });
  }
  it('any order of the radices gives the same transform (Ns is the product of the stages before)', () => {
    const n = 128;
    const random = seededRandom(5);
    const input = Float64Array.from({ length: 2 * n }, () => random() - 0.5);
    const good = stockhamMixedInverse(input, n);
    const reordered = stockhamMixedInverse(input, n, [4, 4, 4, 2]);
    for (let i = 0; i < 2 * n; i++) expect(reordered[i]).toBeCloseTo(good[i], 9);
  });
  // Ns doubled as the radix-2 passes step it.
  it('negative control: radix-4 stages with Ns doubled after each do not give the inverse', () => {
    const n = 64;
    const random = seededRandom(6);
    const input = Float64Array.from({ length: 2 * n }, () => random() - 0.5);
    const good = stockhamMixedInverse(input, n);
    let wrong: Float64Array = input;
    for (let half = 1, s = 0; s < 3; s++, half *= 2) wrong = stockhamRadixStage(wrong, n, half, 4);
    const maxDiff = Math.max(...Array.from(good, (v, i) => Math.abs(v - wrong[i])));
    expect(maxDiff).toBeGreaterThan(1);
  });
});
