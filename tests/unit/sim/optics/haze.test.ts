import { describe, expect, it } from 'vitest';
import { AEROSOL_SCALE_HEIGHT, hazeExtinction, hazeOpticalDepth, hazeWeight, meanDecay } from '../../../../src/sim/optics/haze';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

/** The optical depth by brute force: the density summed at the midpoints of many steps along the path. */
function bruteForceDepth(extinction: number, eyeHeight: number, pointHeight: number, distance: number, steps = 20_000): number {
  let sum = 0;
  for (let i = 0; i < steps; i++) {
    const y = eyeHeight + ((i + 0.5) / steps) * (pointHeight - eyeHeight);
    sum += extinction * Math.exp(-y / AEROSOL_SCALE_HEIGHT);
  }
  return (sum * distance) / steps;
}

describe('haze (Koschmieder, aerosols thinning with height)', () => {
  it('has Koschmieder’s extinction, 3.912 / V: 1.956·10⁻⁴ m⁻¹ for 20 km, 1.2·10⁻³ for 3.26 km', () => {
    expect(hazeExtinction(20_000)).toBeCloseTo(1.956e-4, 7);
    expect(hazeExtinction(3_260)).toBeCloseTo(1.2e-3, 5);
  });

  it('leaves a dark object 2 % of its contrast at the visibility, along the sea', () => {
    const beta = hazeExtinction(20_000);
    expect(1 - hazeWeight(beta, 0, 0, 20_000)).toBeCloseTo(0.02, 10);
    // Control: the WMO's 5 % threshold (3.0 / V) does not.
    expect(Math.abs(Math.exp(-3.0) - 0.02)).toBeGreaterThan(0.02);
  });

  // Control: the height change taken with its sign flipped fails.
  it('matches the path integrated by brute force on 200 seeded paths, within 1e-6 relative', () => {
    const random = seededRandom(17);
    let worst = 0;
    let worstFlipped = 0;
    for (let i = 0; i < 200; i++) {
      const beta = hazeExtinction(1_000 + random() * 59_000);
      const eye = random() < 0.2 ? random() * 3 : random() * 10_000;
      const point = (random() - 0.5) * 10;
      const distance = Math.abs(eye - point) + random() * 40_000;
      const exact = bruteForceDepth(beta, eye, point, distance);
      worst = Math.max(worst, Math.abs(hazeOpticalDepth(beta, eye, point, distance) - exact) / exact);
      const flipped = beta * distance * Math.exp(-eye / AEROSOL_SCALE_HEIGHT) * meanDecay((eye - point) / AEROSOL_SCALE_HEIGHT);
      worstFlipped = Math.max(worstFlipped, Math.abs(flipped - exact) / exact);
    }
    expect(worst).toBeLessThan(1e-6);
    expect(worstFlipped).toBeGreaterThan(0.5);
  });

  it('clears the sea seen from above: from 500 m, 900 m of slant path weighs 0.82 of the same path along the sea', () => {
    const beta = hazeExtinction(20_000);
    const slant = hazeOpticalDepth(beta, 500, 0, 900);
    const along = hazeOpticalDepth(beta, 0, 0, 900);
    expect(slant / along).toBeCloseTo((AEROSOL_SCALE_HEIGHT / 500) * (1 - Math.exp(-500 / AEROSOL_SCALE_HEIGHT)), 10);
    expect(slant / along).toBeCloseTo(0.818, 3);
    // From 5 km up, 13 km of path to the sea holds less than half the haze of 13 km along it.
    expect(hazeOpticalDepth(beta, 5_000, 0, 13_000) / hazeOpticalDepth(beta, 0, 0, 13_000)).toBeLessThan(0.25);
  });

  it('takes the series near x = 0, continuous with the quotient', () => {
    expect(meanDecay(0)).toBe(1);
    const series = (x: number) => 1 - x / 2 + (x * x) / 6;
    for (const x of [-1e-5, 0.99e-4, 1.01e-4, 1e-2, -0.3])
      expect(Math.abs(meanDecay(x) - series(x))).toBeLessThan(Math.max(1e-9, Math.abs(x) ** 3 / 20));
  });
});
