import { describe, expect, it } from 'vitest';
import {
  DEFAULT_NEAR,
  MARGIN_PER_NEAR,
  NEAR_FLOOR,
  nearForClearance,
  nearPlaneDrop,
  type ViewAxes,
} from '../../../../src/render/ocean/nearPlane';

const tan = Math.tan((55 * Math.PI) / 360);
const level: ViewAxes = { forwardY: 0, upY: 1, rightY: 0, tanHalfFov: tan, aspect: 16 / 9 };

/** The lowest of a dense grid of near-plane points for a camera pitched by `pitch` (rad, negative down). */
function lowestNearPoint(pitch: number, near: number): number {
  let lowest = Infinity;
  for (let i = 0; i <= 20; i++)
    for (let j = 0; j <= 20; j++) {
      const sy = -1 + i / 10;
      const y = near * (Math.sin(pitch) + sy * tan * Math.cos(pitch));
      lowest = Math.min(lowest, y);
    }
  return lowest;
}

describe("the near plane from the eye's clearance", () => {
  it('keeps the default near plane for an eye well above the water or under it', () => {
    expect(nearForClearance(5, level)).toBe(DEFAULT_NEAR);
    expect(nearForClearance(-0.05, level)).toBe(DEFAULT_NEAR);
    expect(nearForClearance(0, level)).toBe(DEFAULT_NEAR);
  });

  it('puts the whole near plane above a flat surface, with the margin, for level and pitched views', () => {
    for (const pitch of [0, -0.3, -1.2, 0.4]) {
      const axes: ViewAxes = { forwardY: Math.sin(pitch), upY: Math.cos(pitch), rightY: 0, tanHalfFov: tan, aspect: 16 / 9 };
      expect(nearPlaneDrop(axes)).toBeCloseTo(-lowestNearPoint(pitch, 1), 9);
      for (const clearance of [0.05, 0.2, 0.45]) {
        const near = nearForClearance(clearance, axes);
        expect(near).toBeGreaterThanOrEqual(NEAR_FLOOR);
        // Above the surface under the eye by at least the sampled test's margin.
        if (near > NEAR_FLOOR) expect(clearance + lowestNearPoint(pitch, near)).toBeGreaterThan(MARGIN_PER_NEAR * near);
      }
    }
    // Level from 5 cm up: about 3 cm (0.05 / 1.75), against the fixed 0.5 m.
    expect(nearForClearance(0.05, level)).toBeCloseTo(0.05 / (tan + 0.5 * Math.sqrt(1 + tan ** 2 * (1 + (16 / 9) ** 2)) + 0.5), 12);
  });
});
