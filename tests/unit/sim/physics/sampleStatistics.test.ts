import { describe, expect, it } from 'vitest';
import { median, percentile } from '../../../../src/sim/physics/sampleStatistics';

describe('median', () => {
  it('is the middle value of an odd count, whatever the order', () => {
    expect(median([9, 1, 5])).toBe(5);
    expect(median([3])).toBe(3);
  });
  it('is the mean of the two middle values of an even count', () => {
    expect(median([4, 1, 3, 2])).toBe(2.5);
    expect(median([10, 20])).toBe(15);
  });
  it('is NaN for no samples and leaves its input unsorted', () => {
    expect(median([])).toBeNaN();
    const samples = [3, 1, 2];
    median(samples);
    expect(samples).toEqual([3, 1, 2]);
  });
});

describe('percentile (nearest rank)', () => {
  const oneToThirty = Array.from({ length: 30 }, (_, k) => 30 - k);
  it('p95 of 30 frames is the second slowest', () => {
    expect(percentile(oneToThirty, 95)).toBe(29);
  });
  it('p95 of 20 frames is the 19th, p50 of 30 the 15th, p100 the slowest', () => {
    expect(
      percentile(
        Array.from({ length: 20 }, (_, k) => k + 1),
        95,
      ),
    ).toBe(19);
    expect(percentile(oneToThirty, 50)).toBe(15);
    expect(percentile(oneToThirty, 100)).toBe(30);
  });
  it('is always one of the samples', () => {
    const samples = [0.3, 7.1, 2.2, 9.9, 4.4];
    for (const p of [1, 10, 33, 50, 80, 95, 99, 100]) expect(samples).toContain(percentile(samples, p));
  });
  it('rejects a percentile outside (0, 100] and gives NaN for no samples', () => {
    expect(() => percentile([1], 0)).toThrow(RangeError);
    expect(() => percentile([1], 101)).toThrow(RangeError);
    expect(() => percentile([1], Number.NaN)).toThrow(RangeError);
    expect(percentile([], 95)).toBeNaN();
  });
});
