import { Matrix4, PerspectiveCamera } from 'three';
import { describe, expect, it } from 'vitest';
import { screenAboveLine } from '../../../../src/render/sky/skyBackground';

/** The clip-space corners of a fan (x, y, 0 per vertex) and whether the point lies inside one of its triangles. */
function fanCovers(fan: number[], x: number, y: number): boolean {
  for (let t = 0; t < fan.length; t += 9) {
    const [ax, ay, bx, by, cx, cy] = [fan[t], fan[t + 1], fan[t + 3], fan[t + 4], fan[t + 6], fan[t + 7]];
    const d1 = (x - bx) * (ay - by) - (ax - bx) * (y - by);
    const d2 = (x - cx) * (by - cy) - (bx - cx) * (y - cy);
    const d3 = (x - ax) * (cy - ay) - (cx - ax) * (y - ay);
    const negative = d1 < -1e-9 || d2 < -1e-9 || d3 < -1e-9;
    const positive = d1 > 1e-9 || d2 > 1e-9 || d3 > 1e-9;
    if (!(negative && positive)) return true;
  }
  return false;
}

/** The ray's height per clip coordinate, as SkyBackground reads it: the second row of rotation × inverse projection. */
function rayHeight(camera: PerspectiveCamera): { a: number; b: number; c: number; at: (x: number, y: number) => number } {
  camera.updateMatrixWorld();
  const m = new Matrix4().extractRotation(camera.matrixWorld).multiply(camera.projectionMatrixInverse);
  const e = m.elements;
  const at = (x: number, y: number) => {
    const d = [e[0] * x + e[4] * y + e[8] + e[12], e[1] * x + e[5] * y + e[9] + e[13], e[2] * x + e[6] * y + e[10] + e[14]];
    return d[1] / Math.hypot(d[0], d[1], d[2]);
  };
  return { a: e[1], b: e[5], c: e[9] + e[13], at };
}

describe('the sky drawn above the horizon only', () => {
  const camera = new PerspectiveCamera(55, 16 / 9, 0.1, 1e8);
  camera.position.set(0, 9, 40);
  camera.lookAt(0, 6, 0);
  const { a, b, c, at } = rayHeight(camera);

  it('covers every pixel whose ray rises, and leaves out those that point well down', () => {
    const fan = screenAboveLine(a, b, c);
    expect(fan.length % 9).toBe(0);
    expect(fan.length / 9).toBeLessThanOrEqual(3);
    let covered = 0;
    for (let i = 0; i <= 40; i++) {
      for (let j = 0; j <= 40; j++) {
        const [x, y] = [-1 + i / 20, -1 + j / 20];
        if (at(x, y) > 1e-6) expect(fanCovers(fan, x, y), `ray rising at ${x}, ${y}`).toBe(true);
        if (at(x, y) < -0.01) expect(fanCovers(fan, x, y), `ray falling at ${x}, ${y}`).toBe(false);
        if (fanCovers(fan, x, y)) covered++;
      }
    }
    // The default camera looks a little down: the sky is under the half of the screen.
    expect(covered / 41 ** 2).toBeGreaterThan(0.3);
    expect(covered / 41 ** 2).toBeLessThan(0.6);
  });

  it('is the whole screen looking up and nothing looking straight down', () => {
    const whole = screenAboveLine(0, 0, 1);
    for (const [x, y] of [
      [-1, -1],
      [1, 1],
      [0.3, -0.9],
    ])
      expect(fanCovers(whole, x, y)).toBe(true);
    expect(screenAboveLine(0, 0, -1)).toEqual([]);
  });

  it('control: the line with its slope turned over leaves rising rays out', () => {
    const flipped = screenAboveLine(a, -b, c);
    let missed = 0;
    for (let j = 0; j <= 40; j++) if (at(0, -1 + j / 20) > 1e-6 && !fanCovers(flipped, 0, -1 + j / 20)) missed++;
    expect(missed).toBeGreaterThan(5);
  });
});
