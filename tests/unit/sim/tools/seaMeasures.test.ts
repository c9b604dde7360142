import { describe, expect, it } from 'vitest';
import { along, horizontalDistance } from '../../../../src/sim/tools/rulerDistance';
import { cursorStep, isCursorKey } from '../../../../src/sim/tools/seaCursor';
import { formatProbeText, isProbeCoordinate, parseProbeText } from '../../../../src/sim/tools/probePlace';

describe('the ruler', () => {
  it('measures the horizontal distance: a 3-4-5 triangle, whatever the heights', () => {
    expect(horizontalDistance({ x: 1, z: 2 }, { x: 4, z: 6 })).toBe(5);
    expect(horizontalDistance({ x: -7, z: 0 }, { x: -7, z: 0 })).toBe(0);
    // Control: counting a 2 m rise from trough to crest would read √29 = 5.39 m, not 5.
    expect(Math.hypot(3, 4, 2)).not.toBeCloseTo(horizontalDistance({ x: 0, z: 0 }, { x: 3, z: 4 }), 1);
  });

  it('samples points along the segment', () => {
    expect(along({ x: 0, z: 10 }, { x: 8, z: 2 }, 0.25)).toEqual({ x: 2, z: 8 });
  });
});

describe('the keyboard’s point on the sea', () => {
  it('moves away from the eye on ↑ and to the viewer’s right on →, for any heading', () => {
    // The default view looks along −z: right is +x.
    expect(cursorStep('ArrowUp', [0, 10, 30], [0, 0, 0], 2)).toEqual([0, -2]);
    expect(cursorStep('ArrowRight', [0, 10, 30], [0, 0, 0], 2)).toEqual([2, 0]);
    // Looking along +x: right is +z.
    const [rx, rz] = cursorStep('ArrowRight', [-5, 3, 0], [5, 0, 0], 1);
    expect(rx).toBeCloseTo(0, 12);
    expect(rz).toBeCloseTo(1, 12);
    const [bx, bz] = cursorStep('ArrowDown', [-5, 3, 0], [5, 0, 0], 1);
    expect([bx, bz]).toEqual([-1, -0]);
    // Straight down there is no heading: ↑ is −z.
    expect(cursorStep('ArrowUp', [1, 20, 1], [1, 0, 1], 1)).toEqual([0, -1]);
    expect(isCursorKey('ArrowLeft')).toBe(true);
    expect(isCursorKey('KeyW')).toBe(false);
  });
});

describe('where a probe may stand (?probe=x,z)', () => {
  it('reads "x,z" in metres and writes it back to the same doubles', () => {
    expect(parseProbeText('13.7,-4.2')).toEqual({ x: 13.7, z: -4.2 });
    expect(parseProbeText(' 0 , 1e3 ')).toEqual({ x: 0, z: 1000 });
    const point = { x: 0.1 + 0.2, z: -1 / 3 };
    expect(parseProbeText(formatProbeText(point))).toEqual(point);
  });

  it('refuses anything else: not two numbers, not finite, beyond ±1e6 m', () => {
    for (const text of ['', '1', '1,2,3', '1,oops', ',2', '1,', 'NaN,0', 'Infinity,0', '2e6,0'])
      expect(parseProbeText(text), text).toBeNull();
    expect(isProbeCoordinate(1e6)).toBe(true);
    expect(isProbeCoordinate('1')).toBe(false);
  });
});
