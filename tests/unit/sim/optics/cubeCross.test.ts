import { describe, expect, it } from 'vitest';
import { CROSS_CELLS, crossDirection, crossPoint, type CrossCell } from '../../../../src/sim/optics/cubeCross';
import { sunDirection } from '../../../../src/sim/optics/sun';

const normalise = (v: number[]) => {
  const length = Math.hypot(...v);
  return v.map((c) => c / length);
};

describe('the cube map unfolded into a cross', () => {
  it('has six cells, one per face, each looking along its own axis', () => {
    expect(CROSS_CELLS.map((c) => c.face).sort()).toEqual(['nx', 'ny', 'nz', 'px', 'py', 'pz']);
    for (const cell of CROSS_CELLS) {
      const axis = { x: 0, y: 1, z: 2 }[cell.face[1] as 'x' | 'y' | 'z'];
      expect(cell.centre[axis]).toBe(cell.face[0] === 'p' ? 1 : -1);
      expect(crossDirection(cell.column + 0.5, cell.row + 0.5)).toEqual(cell.centre);
    }
    expect(crossDirection(0.5, 0.5)).toBeNull();
    expect(crossDirection(3.5, 2.5)).toBeNull();
  });

  /** The largest difference between the unit directions either side of the cross's seams, the wrapping one included. */
  function worstSeam(cells: readonly CrossCell[]): number {
    const pairs: [number, number, number, number][] = [];
    for (let t = 0.05; t < 1; t += 0.1) {
      for (let column = 0; column < 3; column++) pairs.push([column + 1 - 1e-9, 1 + t, column + 1 + 1e-9, 1 + t]);
      pairs.push([1 + t, 1 - 1e-9, 1 + t, 1 + 1e-9], [1 + t, 2 - 1e-9, 1 + t, 2 + 1e-9]);
      // The horizon wraps: the right edge of +z is the left edge of −x.
      pairs.push([4 - 1e-9, 1 + t, 1e-9, 1 + t]);
    }
    let worst = 0;
    for (const [x0, y0, x1, y1] of pairs) {
      const a = normalise(crossDirection(x0, y0, cells)!);
      const b = normalise(crossDirection(x1, y1, cells)!);
      worst = Math.max(worst, ...a.map((c, k) => Math.abs(c - b[k])));
    }
    return worst;
  }

  // Control: the sky face upside down.
  it('shows the same direction on both sides of every seam, including the one round the horizon', () => {
    expect(worstSeam(CROSS_CELLS)).toBeLessThan(1e-6);
    const flipped = CROSS_CELLS.map((c) => (c.face === 'py' ? { ...c, up: [0, 0, -1] as [number, number, number] } : c));
    expect(worstSeam(flipped)).toBeGreaterThan(0.5);
  });

  it('finds a direction where it is drawn: crossPoint undoes crossDirection', () => {
    for (let y = 0.03; y < 3; y += 0.11) {
      for (let x = 0.03; x < 4; x += 0.13) {
        const direction = crossDirection(x, y);
        if (!direction) continue;
        const [px, py] = crossPoint(direction);
        expect(px).toBeCloseTo(x, 9);
        expect(py).toBeCloseTo(y, 9);
      }
    }
  });

  it('puts the default sun (azimuth 20°, elevation 18°) ahead, right of centre and above the horizon', () => {
    const [x, y] = crossPoint(sunDirection(18, 20));
    expect(Math.floor(x)).toBe(1);
    expect(Math.floor(y)).toBe(1);
    expect(x).toBeGreaterThan(1.5);
    expect(y).toBeLessThan(1.5);
  });
});
