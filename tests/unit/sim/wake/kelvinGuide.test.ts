import { describe, expect, it } from 'vitest';
import { forwardOf } from '../../../../src/sim/boat/boatPose';
import { KELVIN_HALF_ANGLE, kelvinGuideLines } from '../../../../src/sim/wake/kelvinGuide';

describe('kelvinGuideLines', () => {
  it.each([0, 1, 2.5, 4.7])('draws two lines 19.47° either side of the stern direction, heading %s rad', (heading) => {
    const [ax, az, px, pz, sx, sz] = kelvinGuideLines(12, -7, heading, 100);
    const [fx, fz] = forwardOf(heading);
    const angle = (ex: number, ez: number) => Math.acos((-(ex - ax) * fx - (ez - az) * fz) / Math.hypot(ex - ax, ez - az));
    expect((angle(px, pz) * 180) / Math.PI).toBeCloseTo(19.4712, 3);
    expect((angle(sx, sz) * 180) / Math.PI).toBeCloseTo(19.4712, 3);
    expect(Math.hypot(px - ax, pz - az)).toBeCloseTo(100, 9);
    // One each side: the cross products with the stern direction have opposite signs.
    const side = (ex: number, ez: number) => -fx * (ez - az) + fz * (ex - ax);
    expect(side(px, pz) * side(sx, sz)).toBeLessThan(0);
    expect(KELVIN_HALF_ANGLE).toBeCloseTo(Math.asin(1 / 3), 15);
  });

  it('measures another angle when the lines are drawn for a heading 3° off (negative control)', () => {
    const heading = 1;
    const [ax, az, px, pz] = kelvinGuideLines(0, 0, heading + (3 * Math.PI) / 180, 100);
    const [fx, fz] = forwardOf(heading);
    const angle = (Math.acos((-(px - ax) * fx - (pz - az) * fz) / Math.hypot(px - ax, pz - az)) * 180) / Math.PI;
    expect(Math.abs(angle - 19.4712)).toBeGreaterThan(1);
  });
});
