import { describe, expect, it } from 'vitest';
import { checkDisturbance, IWAVE_SPACING } from '../../src/sim/iwave/interactiveField';

describe('disturb() arguments', () => {
  it('throws a RangeError naming the argument for non-finite or out-of-range input', () => {
    expect(() => checkDisturbance(Number.NaN, 0)).toThrow(/x and z/);
    expect(() => checkDisturbance(0, Infinity)).toThrow(/x and z/);
    expect(() => checkDisturbance(0, 0, { radius: -1 })).toThrow(/radius/);
    expect(() => checkDisturbance(0, 0, { radius: 11 })).toThrow(/radius/);
    expect(() => checkDisturbance(0, 0, { height: 2.5 })).toThrow(/height/);
    expect(() => checkDisturbance(0, 0, { height: Number.NaN })).toThrow(/height/);
  });

  it('raises a radius under one texel to one texel and says so; a fair one passes unchanged with no notice', () => {
    const small = checkDisturbance(1, 2, { radius: 0.1, height: 0.2 });
    expect(small.disturbance).toEqual({ x: 1, z: 2, radius: IWAVE_SPACING, height: 0.2 });
    expect(small.notices).toHaveLength(1);
    expect(small.notices[0]).toMatch(/raised to 0.5 m/);
    const fair = checkDisturbance(1, 2, { radius: 1.5, height: -0.4 });
    expect(fair.disturbance).toEqual({ x: 1, z: 2, radius: 1.5, height: -0.4 });
    expect(fair.notices).toEqual([]);
  });
});
