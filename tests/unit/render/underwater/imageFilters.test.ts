import { describe, expect, it } from 'vitest';
import { gaussianKernel, linearSampledKernel, type LinearSampledKernel } from '../../../../src/render/underwater/gaussianKernel';
import { highFrequencyEnergy } from '../../../support/imageEnergy';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

function grey(values: number[][]): Uint8Array {
  const h = values.length;
  const w = values[0].length;
  const out = new Uint8Array(w * h * 4);
  values.flat().forEach((v, i) => out.set([v, v, v, 255], i * 4));
  return out;
}

describe('gaussianKernel', () => {
  it('sums to 1 over both sides, follows exp(−i²/2σ²) and stops at 3σ', () => {
    for (const sigma of [0.5, 1.5, 3, 7.3]) {
      const w = gaussianKernel(sigma, 24);
      const radius = Math.ceil(3 * sigma);
      let total = w[0];
      for (let i = 1; i < w.length; i++) total += 2 * w[i];
      expect(total).toBeCloseTo(1, 6);
      for (let i = 1; i <= radius; i++) expect(w[i] / w[0]).toBeCloseTo(Math.exp(-(i * i) / (2 * sigma * sigma)), 6);
      for (let i = radius + 1; i < w.length; i++) expect(w[i]).toBe(0);
    }
  });

  it('is the identity at σ = 0, is capped at maxRadius, and rejects a negative σ', () => {
    expect(Array.from(gaussianKernel(0, 4))).toEqual([1, 0, 0, 0, 0]);
    const capped = gaussianKernel(10, 4);
    expect(capped.length).toBe(5);
    expect(capped[0] + 2 * (capped[1] + capped[2] + capped[3] + capped[4])).toBeCloseTo(1, 6);
    expect(() => gaussianKernel(-1, 4)).toThrow(RangeError);
  });
});

describe('linearSampledKernel', () => {
  const random = seededRandom(14);
  const signal = Array.from({ length: 64 }, () => random());
  /** What a bilinear (here linear) texture fetch returns between texels. */
  const fetch = (x: number) => {
    const i = Math.floor(x);
    return signal[i] + (x - i) * (signal[i + 1] - signal[i]);
  };
  const discreteBlur = (w: Float32Array, c: number) =>
    w.reduce((sum, wi, i) => sum + (i === 0 ? wi * signal[c] : wi * (signal[c + i] + signal[c - i])), 0);
  const linearBlur = (k: LinearSampledKernel, c: number) => {
    let sum = k.weights[0] * signal[c];
    for (let t = 1; t < k.taps; t++) sum += k.weights[t] * (fetch(c + k.offsets[t]) + fetch(c - k.offsets[t]));
    return sum;
  };

  it('gives the discrete Gaussian convolution with about half the taps', () => {
    for (const sigma of [0.75, 1.5, 2.2, 4]) {
      const k = linearSampledKernel(sigma, 12, 8);
      const radius = Math.ceil(3 * sigma);
      expect(k.taps).toBe(1 + Math.ceil(radius / 2));
      const worst = Math.max(...[20, 31, 40].map((c) => Math.abs(linearBlur(k, c) - discreteBlur(gaussianKernel(sigma, 12), c))));
      // Measured: below 1e-7 (float32 weights); the planted fault below is 100 times larger.
      expect(worst).toBeLessThan(1e-6);
    }
  });

  it('negative control: pair taps at the midpoint of the two texels are not the same blur', () => {
    const k = linearSampledKernel(1.5, 12, 8);
    const midpoints = { ...k, offsets: k.offsets.map((_, t) => (t === 0 ? 0 : 2 * t - 0.5)) };
    const worst = Math.max(...[20, 31, 40].map((c) => Math.abs(linearBlur(midpoints, c) - discreteBlur(gaussianKernel(1.5, 12), c))));
    expect(worst).toBeGreaterThan(1e-4);
  });

  it('is the identity at σ = 0 and refuses a kernel longer than the shader loop', () => {
    const k = linearSampledKernel(0, 12, 8);
    expect(k.taps).toBe(1);
    expect(k.weights[0]).toBe(1);
    expect(() => linearSampledKernel(4, 12, 4)).toThrow(RangeError);
  });
});

describe('highFrequencyEnergy', () => {
  it('is 0 for a flat image and for a linear ramp', () => {
    expect(
      highFrequencyEnergy(
        grey([
          [7, 7, 7],
          [7, 7, 7],
          [7, 7, 7],
        ]),
        3,
        3,
      ),
    ).toBe(0);
    const ramp = Array.from({ length: 5 }, (_, y) => Array.from({ length: 6 }, (_, x) => 10 * x + 3 * y));
    expect(highFrequencyEnergy(grey(ramp), 6, 5)).toBeCloseTo(0, 9);
  });

  it('is the squared Laplacian of a single bright pixel, exactly', () => {
    // Centre pixel 100 among zeros: Laplacian −400 at the only interior pixel. Luma weights sum to 1.
    expect(
      highFrequencyEnergy(
        grey([
          [0, 0, 0],
          [0, 100, 0],
          [0, 0, 0],
        ]),
        3,
        3,
      ),
    ).toBeCloseTo(160000, 6);
  });

  it('drops when seeded random noise (seed 11) is box-blurred', () => {
    const random = seededRandom(11);
    const size = 32;
    const noise = Array.from({ length: size }, () => Array.from({ length: size }, () => Math.floor(random() * 256)));
    const blurred = noise.map((row, y) =>
      row.map((_, x) => {
        let sum = 0;
        let count = 0;
        for (let dy = -1; dy <= 1; dy++)
          for (let dx = -1; dx <= 1; dx++) {
            const v = noise[y + dy]?.[x + dx];
            if (v !== undefined) {
              sum += v;
              count++;
            }
          }
        return Math.round(sum / count);
      }),
    );
    const before = highFrequencyEnergy(grey(noise), size, size);
    const after = highFrequencyEnergy(grey(blurred), size, size);
    expect(after).toBeLessThan(before * 0.2);
  });

  it('rejects a buffer of the wrong size', () => {
    expect(() => highFrequencyEnergy(new Uint8Array(10), 3, 3)).toThrow(RangeError);
  });
});
