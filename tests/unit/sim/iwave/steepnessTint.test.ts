import { describe, expect, it } from 'vitest';
import {
  FOAM_FROM_SLOPE,
  STOKES_LIMIT_SLOPE,
  TINT_FROM_SLOPE,
  TINT_STRENGTH,
  fieldFoam,
  fieldTint,
} from '../../../../src/sim/iwave/steepnessTint';

describe('the steep water of the interactive waves', () => {
  it('takes Stokes’s limiting wave for its scale: a 120° crest, slope tan 30° = 0.577 (Stokes 1880)', () => {
    expect(STOKES_LIMIT_SLOPE).toBeCloseTo(0.5774, 4);
    expect(FOAM_FROM_SLOPE).toBeLessThan(STOKES_LIMIT_SLOPE);
    expect(TINT_FROM_SLOPE).toBeLessThan(FOAM_FROM_SLOPE);
  });

  // Foams as a wave nears the limit.
  it('leaves gentle water alone, tints steeper water, foams near the limit, whatever the slope’s direction', () => {
    expect(fieldTint(0.02, 0)).toBe(0);
    expect(fieldFoam(0.3, 0)).toBe(0);
    expect(fieldTint(0.2, 0.1)).toBeGreaterThan(0);
    expect(fieldTint(0.2, 0.1)).toBeLessThan(TINT_STRENGTH);
    expect(fieldTint(0, FOAM_FROM_SLOPE)).toBe(TINT_STRENGTH);
    expect(fieldFoam(0, -STOKES_LIMIT_SLOPE)).toBe(1);
    expect(fieldFoam(0.3, 0.3)).toBeCloseTo(fieldFoam(0, Math.hypot(0.3, 0.3)), 12);
    // Monotone in the slope.
    let before = -1;
    for (let s = 0; s <= 0.7; s += 0.01) {
      const now = fieldTint(s, 0) + fieldFoam(s, 0);
      expect(now).toBeGreaterThanOrEqual(before);
      before = now;
    }
  });
});
