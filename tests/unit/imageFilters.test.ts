import { describe, expect, it } from 'vitest';
import { gaussianKernel } from '../../src/sim/gaussianKernel';
import { highFrequencyEnergy } from '../support/imageEnergy';
import { seededRandom } from '../../src/sim/integerHash';

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

describe('highFrequencyEnergy', () => {
  it('is 0 for a flat image and for a linear ramp', () => {
    expect(highFrequencyEnergy(grey([[7, 7, 7], [7, 7, 7], [7, 7, 7]]), 3, 3)).toBe(0);
    const ramp = Array.from({ length: 5 }, (_, y) => Array.from({ length: 6 }, (_, x) => 10 * x + 3 * y));
    expect(highFrequencyEnergy(grey(ramp), 6, 5)).toBeCloseTo(0, 9);
  });

  it('is the squared Laplacian of a single bright pixel, exactly', () => {
    // Centre pixel 100 among zeros: Laplacian −400 at the only interior pixel. Luma weights sum to 1.
    expect(highFrequencyEnergy(grey([[0, 0, 0], [0, 100, 0], [0, 0, 0]]), 3, 3)).toBeCloseTo(160000, 6);
  });

  it('drops when seeded random noise (seed 11) is box-blurred', () => {
    const random = seededRandom(11);
    const size = 32;
    const noise = Array.from({ length: size }, () => Array.from({ length: size }, () => Math.floor(random() * 256)));
    const blurred = noise.map((row, y) =>
      row.map((_, x) => {
        let sum = 0;
        let count = 0;
        for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) {
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
