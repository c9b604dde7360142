import { describe, expect, it } from 'vitest';
import { gerstnerOriginPhases, tileOriginTexels } from '../../../../src/sim/waves/originPhases';

// Distance between two phases in turns, modulo whole turns.
const turnDistance = (a: number, b: number) => {
  const d = (((a - b) % 1) + 1) % 1;
  return Math.min(d, 1 - d);
};

describe('phases relative to the render origin', () => {
  const waves = [
    { cx: 0.0123456789, cz: -0.0456789 },
    { cx: 0.731, cz: 0.2172 },
    { cx: -1.93, cz: 0.0007 },
  ];
  const time = [0.25, 0.9, 0.01];

  it('gives the absolute angle at origin + r from the relative point r', () => {
    const [ox, oz] = [1_003_520, -999_424];
    const near = gerstnerOriginPhases(waves, time, ox, oz);
    for (const [rx, rz] of [
      [0, 0],
      [12.375, -40.5],
      [-1800.25, 950.125],
    ]) {
      waves.forEach((w, i) => {
        // The absolute angle in double precision (big products reduced with care: exact to ~1e-9 turns).
        const absolute = time[i] + w.cx * (ox + rx) + w.cz * (oz + rz);
        const relative = near[i] + w.cx * rx + w.cz * rz;
        expect(turnDistance(absolute, relative)).toBeLessThan(1e-8);
      });
    }
  });

  it('is the time phase itself at the world origin', () => {
    expect(Array.from(gerstnerOriginPhases(waves, time, 0, 0))).toEqual(time);
  });

  it('places the origin in a repeating tile so that relative reads land on the same texel', () => {
    const size = 237.5;
    const n = 256;
    const [ox, oz] = [999_424, -1_003_520];
    const [tx, tz] = tileOriginTexels(size, n, ox, oz);
    expect(tx).toBeGreaterThanOrEqual(0);
    expect(tx).toBeLessThan(n);
    expect(tz).toBeGreaterThanOrEqual(0);
    expect(tz).toBeLessThan(n);
    for (const r of [0, 3.3, -700.125]) {
      const wrapped = (u: number) => ((u % n) + n) % n;
      expect(Math.abs(wrapped((ox + r) * (n / size)) - wrapped(r * (n / size) + tx))).toBeLessThan(1e-6);
      expect(Math.abs(wrapped((oz + r) * (n / size)) - wrapped(r * (n / size) + tz))).toBeLessThan(1e-6);
    }
    expect(tileOriginTexels(size, n, 0, 0)).toEqual([0, 0]);
  });
});
