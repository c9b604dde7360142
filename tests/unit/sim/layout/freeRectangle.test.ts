import { describe, expect, it } from 'vitest';
import { largestFreeRectangle } from '../../../../src/sim/layout/freeRectangle';
import { cellGrid, squaresInRow } from '../../../../src/sim/layout/figureLayout';
import { contains, overlaps, type Rect } from '../../../../src/sim/layout/rect';

const area = (r: Rect) => r.width * r.height;

/** Brute force on a 2-px lattice: the largest obstacle-free rectangle with corners on the lattice. */
function bruteForce(view: Rect, obstacles: Rect[]): number {
  let best = 0;
  for (let x0 = view.x; x0 < view.x + view.width; x0 += 2) {
    for (let x1 = x0 + 2; x1 <= view.x + view.width; x1 += 2) {
      for (let y0 = view.y; y0 < view.y + view.height; y0 += 2) {
        for (let y1 = y0 + 2; y1 <= view.y + view.height; y1 += 2) {
          const r = { x: x0, y: y0, width: x1 - x0, height: y1 - y0 };
          if (area(r) > best && !obstacles.some((o) => overlaps(o, r))) best = area(r);
        }
      }
    }
  }
  return best;
}

describe('the free part of the canvas', () => {
  it('a laptop, 1366 × 768: the strip between the lessons drawer (left) and the panel (right)', () => {
    const view = { x: 0, y: 0, width: 1366, height: 768 };
    const drawer = { x: 12, y: 12, width: 272, height: 600 };
    const panel = { x: 1109, y: 0, width: 245, height: 550 };
    expect(largestFreeRectangle(view, [drawer, panel])).toEqual({ x: 284, y: 0, width: 825, height: 768 });
  });

  it('a phone, 390 × 844: above the drawer’s bottom sheet and below the folded panel’s title bar', () => {
    const view = { x: 0, y: 0, width: 390, height: 844 };
    const sheet = { x: 0, y: 506, width: 390, height: 338 };
    const title = { x: 133, y: 0, width: 245, height: 24 };
    expect(largestFreeRectangle(view, [sheet, title])).toEqual({ x: 0, y: 24, width: 390, height: 482 });
  });

  it('no obstacles, or obstacles outside the view: the whole view', () => {
    const view = { x: 0, y: 0, width: 320, height: 180 };
    expect(largestFreeRectangle(view, [])).toEqual(view);
    expect(largestFreeRectangle(view, [{ x: 400, y: 0, width: 50, height: 50 }])).toEqual(view);
  });

  it('is the largest and free, against brute force on seeded random obstacles (seed 7)', () => {
    let state = 7;
    const random = () => (state = (state * 1103515245 + 12345) % 2147483648) / 2147483648;
    for (let trial = 0; trial < 12; trial++) {
      const view = { x: 0, y: 0, width: 60, height: 40 };
      const obstacles = Array.from({ length: 1 + (trial % 3) }, () => ({
        x: Math.round(random() * 25) * 2,
        y: Math.round(random() * 15) * 2,
        width: 2 + Math.round(random() * 10) * 2,
        height: 2 + Math.round(random() * 10) * 2,
      }));
      const found = largestFreeRectangle(view, obstacles);
      expect(
        obstacles.some((o) => overlaps(o, found)),
        `trial ${trial}`,
      ).toBe(false);
      expect(contains(view, found)).toBe(true);
      expect(area(found), `trial ${trial}`).toBe(bruteForce(view, obstacles));
      // Control: the whole view, which the check must refuse since obstacles lie in it.
      expect(obstacles.some((o) => overlaps(o, view))).toBe(true);
    }
  });
});

describe('figures laid out in the free part', () => {
  it('squares side by side fill the limiting direction, centred, with room for their captions', () => {
    const free = { x: 284, y: 0, width: 825, height: 768 };
    const [a, b] = squaresInRow(2, free);
    expect(a.width).toBe(a.height);
    expect(b.x - (a.x + a.width)).toBe(12);
    // 825 wide for two squares limits them: (825 − 24 − 12) / 2 = 394.
    expect(a.width).toBe(394);
    expect(Math.abs(a.x - free.x - (free.x + free.width - (b.x + b.width)))).toBeLessThanOrEqual(1);
    expect(contains(free, { ...a, height: a.height + 34 })).toBe(true);
    for (const count of [1, 2, 3])
      for (const square of squaresInRow(count, { x: 0, y: 24, width: 390, height: 482 }))
        expect(contains({ x: 0, y: 24, width: 390, height: 482 }, square)).toBe(true);
  });

  it('the cube’s cross is 4 × 3 cells inside the area', () => {
    const { box, cell } = cellGrid(4, 3, { x: 0, y: 24, width: 390, height: 482 });
    expect(cell).toBe(Math.floor((390 - 24) / 4));
    expect(box.width).toBe(4 * cell);
    expect(contains({ x: 0, y: 24, width: 390, height: 482 }, box)).toBe(true);
  });
});
