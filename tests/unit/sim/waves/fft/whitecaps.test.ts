import { describe, expect, it } from 'vitest';
import { upperNormalQuantile, whitecapCoverage } from '../../../../../src/sim/waves/fft/whitecaps';

describe('whitecaps', () => {
  it("follows Monahan & O'Muircheartaigh (1980): about 1 % at 10 m/s, 10 % at 20 m/s", () => {
    expect(whitecapCoverage(10)).toBeCloseTo(0.00987, 4);
    expect(whitecapCoverage(20)).toBeCloseTo(0.105, 3);
    expect(whitecapCoverage(4)).toBeLessThan(0.001);
  });

  it("normal quantiles within 4.5e-4 (plus the tables' rounding) of 1.2816, 1.6449, 2.3263, 3.0902", () => {
    for (const [p, z] of [
      [0.1, 1.2816],
      [0.05, 1.6449],
      [0.01, 2.3263],
      [0.001, 3.0902],
    ])
      expect(Math.abs(upperNormalQuantile(p) - z)).toBeLessThan(4.5e-4 + 5e-5);
  });
});
