import { describe, expect, it } from 'vitest';
import { autocorrelation, peakBeyond } from '../../../support/autocorrelation';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

describe('the image autocorrelation the no-tiling test reads (tests/support/autocorrelation.ts)', () => {
  const width = 120;
  const height = 80;

  // ρ ≈ 1 at (30, 0), matching a brute-force sum (seed 3); independent noise has no peak past 10 px above
  // 0.05 once averaged over 3 × 3 lags (seed 4).
  it('finds a pattern that repeats every 30 pixels, and no peak in independent noise', () => {
    const random = seededRandom(3);
    const tile = Array.from({ length: 30 * height }, () => (random() < 0.1 ? 1 : 0));
    const tiled = Float64Array.from({ length: width * height }, (_, i) => tile[((i % width) % 30) + 30 * Math.floor(i / width)]);
    const acf = autocorrelation(tiled, width, height);
    expect(acf.at(30, 0)).toBeCloseTo(1, 6);
    expect(acf.at(0, 0)).toBeCloseTo(1, 6);
    // Brute force at one lag.
    const mean = tiled.reduce((a, b) => a + b, 0) / tiled.length;
    const variance = tiled.reduce((a, b) => a + (b - mean) ** 2, 0) / tiled.length;
    let sum = 0;
    let pairs = 0;
    for (let y = 0; y < height - 5; y++)
      for (let x = 0; x < width - 7; x++) {
        sum += (tiled[y * width + x] - mean) * (tiled[(y + 5) * width + x + 7] - mean);
        pairs++;
      }
    expect(acf.at(7, 5)).toBeCloseTo(sum / pairs / variance, 9);
    expect(peakBeyond(acf, 10, 0).rho).toBeGreaterThan(0.9);

    const noise = seededRandom(4);
    const independent = Float64Array.from({ length: width * height }, () => (noise() < 0.1 ? 1 : 0));
    expect(peakBeyond(autocorrelation(independent, width, height), 10, 1).rho).toBeLessThan(0.05);
  });
});
