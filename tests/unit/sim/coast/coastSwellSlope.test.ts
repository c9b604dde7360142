import { describe, expect, it } from 'vitest';
import { coastSwellWithSlope } from '../../../../src/sim/coast/coastSwellSlope';
import { coastSwellHeight, coastSwellNormal } from '../../../../src/sim/coast/coastFieldSampling';
import { buildCoastField } from '../../../../src/sim/coast/coastSwellField';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

const beach = buildCoastField(
  { bathymetry: 'beach', beachSlope: 0.02, deepDepth: 1000, swellHeight: 1.5, swellPeriod: 10, swellDirection: 15, seed: 1 },
  128,
)!;
const island = buildCoastField(
  { bathymetry: 'island', beachSlope: 0.05, deepDepth: 1000, swellHeight: 2, swellPeriod: 8, swellDirection: 0, seed: 1 },
  128,
)!;

/** Seeded points inside and beyond each field's grid (seed 4901), at three times. */
function points(seed: number, field: typeof beach): [number, number, number][] {
  const random = seededRandom(seed);
  const span = field.spacing * (field.resolution - 1);
  return Array.from({ length: 300 }, () => [
    field.originX - 0.2 * span + random() * 1.4 * span,
    field.originZ - 0.2 * span + random() * 1.4 * span,
    [0, 3.7, 1234.5][Math.floor(random() * 3)],
  ]);
}

describe("the swell's slope from one reading of the field", () => {
  it.each([
    ['beach', beach],
    ['island', island],
  ] as const)('gives sampleCoastField’s height and the central differences’ slope: %s, seed 4901', (_name, field) => {
    let worstSlope = 0;
    for (const [x, z, t] of points(4901, field)) {
      const [height, slopeX, slopeZ] = coastSwellWithSlope(field, x, z, t);
      expect(height).toBeCloseTo(coastSwellHeight(field, x, z, t), 9);
      const n = coastSwellNormal(field, x, z, t);
      worstSlope = Math.max(worstSlope, Math.abs(slopeX + n[0] / n[1]), Math.abs(slopeZ + n[2] / n[1]));
    }
    // Central differences over ±0.25 m straddle a cell's edge for a few points: a small difference there.
    expect(worstSlope).toBeLessThan(0.02);
  });

  it('negative control: the slope a quarter period late is far from the differences (the check can fail)', () => {
    const [x, z, t] = [300, 0, 2];
    const [, slopeX] = coastSwellWithSlope(beach, x, z, t + 2.5);
    const n = coastSwellNormal(beach, x, z, t);
    expect(Math.abs(slopeX + n[0] / n[1])).toBeGreaterThan(0.02);
  });
});
