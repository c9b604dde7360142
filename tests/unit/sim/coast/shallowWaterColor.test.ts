import { describe, expect, it } from 'vitest';
import { diffuseAttenuation, SAND_ALBEDO, shallowWaterReflectance } from '../../../../src/sim/coast/shallowWaterColor';
import { bodyColor } from '../../../../src/sim/optics/waterColor';

describe("the shallows' colour", () => {
  it('is the sand on the shore and the deep water’s own colour over a deep bed', () => {
    expect(shallowWaterReflectance(0)).toEqual([...SAND_ALBEDO]);
    const deep = bodyColor();
    shallowWaterReflectance(400).forEach((r, i) => expect(r).toBeCloseTo(deep[i], 6));
  });

  it('loses red first: a few metres over sand it is blue-green (turquoise), not the sand’s colour', () => {
    const [r, g, b] = shallowWaterReflectance(3);
    expect(g).toBeGreaterThan(2 * r);
    expect(b).toBeGreaterThan(2 * r);
    expect(SAND_ALBEDO[0]).toBeGreaterThan(SAND_ALBEDO[1]);
  });

  it('darkens with depth in every channel', () => {
    const depths = [0, 1, 3, 10, 30, 60];
    for (let c = 0; c < 3; c++) {
      const values = depths.map((d) => shallowWaterReflectance(d)[c]);
      for (let i = 1; i < values.length; i++) expect(values[i]).toBeLessThan(values[i - 1]);
    }
  });

  it('attenuates red most and blue least, as pure water absorbs', () => {
    const [r, g, b] = diffuseAttenuation();
    expect(r).toBeGreaterThan(g);
    expect(g).toBeGreaterThan(b);
  });

  it('negative control: a black bed never makes the water brighter than deep water', () => {
    const deep = bodyColor();
    shallowWaterReflectance(2, [0, 0, 0]).forEach((r, i) => expect(r).toBeLessThanOrEqual(deep[i]));
  });
});
