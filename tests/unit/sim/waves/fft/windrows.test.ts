import { describe, expect, it } from 'vitest';
import { breakupNoise, foamGroupShare, FOAM_GROUP_SHARE_MEAN } from '../../../../../src/sim/waves/fft/foamBreakup';
import { foamDriftVelocity } from '../../../../../src/sim/waves/fft/foamDrift';
import {
  BEAUFORT_7_FROM,
  BEAUFORT_9_FROM,
  windrowCoordinates,
  windrowGathering,
  windrowLattice,
  WINDROW_GATHER_MEAN,
  windrowShare,
  windrowStrength,
  type WindrowLattice,
} from '../../../../../src/sim/waves/fft/windrows';
import { valueNoise } from '../../../../../src/sim/noise/valueNoise';

const SEA = { windSpeed: 20, windDirection: 20 };

/** The mean of f over a grid of points that falls on no lattice alignment, for several seeds. */
function meanOver(f: (u: number, v: number, seed: number) => number): number {
  let sum = 0;
  let count = 0;
  for (const seed of [1, 7, 1234]) {
    for (let j = 0; j < 300; j++) {
      for (let i = 0; i < 300; i++) {
        sum += f(i * 0.377 + 0.11, j * 0.413 + 0.07, seed);
        count++;
      }
    }
  }
  return sum / count;
}

/** The windrows' share at world (x, z), through the lattice as the shader reads it (render origin at ox, oz). */
function shareAt(lattice: WindrowLattice, ox: number, oz: number, x: number, z: number, seed: number): number {
  const [u, v] = windrowCoordinates(lattice, x - ox, z - oz);
  return windrowShare(u, v, seed, 1, 0);
}

/** Correlation of the share field with itself `lag` metres away along the unit direction (dx, dz). */
function correlationAt(lattice: WindrowLattice, dx: number, dz: number, lag: number): number {
  const values: [number, number][] = [];
  for (let j = 0; j < 120; j++) {
    for (let i = 0; i < 120; i++) {
      const x = i * 2.37;
      const z = j * 2.41;
      values.push([shareAt(lattice, 0, 0, x, z, 3), shareAt(lattice, 0, 0, x + lag * dx, z + lag * dz, 3)]);
    }
  }
  const mean = values.reduce((s, [a, b]) => s + a + b, 0) / (2 * values.length);
  let num = 0;
  let den = 0;
  for (const [a, b] of values) {
    num += (a - mean) * (b - mean);
    den += 0.5 * ((a - mean) ** 2 + (b - mean) ** 2);
  }
  return num / den;
}

describe('windrows (src/sim/waves/fft/windrows.ts)', () => {
  it('follow the Beaufort scale: none below force 7 (13.9 m/s), all of them from force 9 (20.8 m/s), growing between', () => {
    expect(windrowStrength(10)).toBe(0);
    expect(windrowStrength(BEAUFORT_7_FROM)).toBe(0);
    expect(windrowStrength(BEAUFORT_9_FROM)).toBe(1);
    expect(windrowStrength(30)).toBe(1);
    let last = 0;
    for (let u = 14; u <= 20.8; u += 0.2) {
      expect(windrowStrength(u)).toBeGreaterThan(last);
      last = windrowStrength(u);
    }
    // The WMO's bounds in m/s come from the Beaufort equation v = 0.836 B^{3/2} m/s, a force's
    // lower bound at B − ½: 13.85 for force 7, 20.72 for force 9, rounded up in the table.
    const beaufortSpeed = (b: number) => 0.836 * b ** 1.5;
    expect(Math.abs(BEAUFORT_7_FROM - beaufortSpeed(6.5))).toBeLessThan(0.1);
    expect(Math.abs(BEAUFORT_9_FROM - beaufortSpeed(8.5))).toBeLessThan(0.1);
  });

  // So the windrows’ share has the groups’ mean.
  it('move the foam, not make it: the gathering’s and the groups’ means are what the constants say', () => {
    expect(meanOver((u, v, seed) => windrowGathering(valueNoise(u, v, seed)))).toBeCloseTo(WINDROW_GATHER_MEAN, 2);
    expect(meanOver((u, v, seed) => foamGroupShare(breakupNoise(u, v, seed)))).toBeCloseTo(FOAM_GROUP_SHARE_MEAN, 2);
    const swept = meanOver((u, v, seed) => windrowShare(u, v, seed, 1, 0));
    expect(Math.abs(swept / FOAM_GROUP_SHARE_MEAN - 1)).toBeLessThan(0.03);
    // Below force 7 the groups decide alone, exactly.
    expect(windrowShare(3.3, 1.7, 5, 0, 0.42)).toBe(0.42);
  });

  // Control: the lattice laid across the wind.
  it('lie along the wind: 12 m downwind the streaks are still there, 12 m across they are not', () => {
    const lattice = windrowLattice(SEA, 0, 0, 0);
    const [wx, wz] = [lattice.axes[0], lattice.axes[1]].map((a) => a / Math.hypot(lattice.axes[0], lattice.axes[1]));
    const along = correlationAt(lattice, wx, wz, 12);
    const across = correlationAt(lattice, -wz, wx, 12);
    expect(along).toBeGreaterThan(0.7);
    expect(Math.abs(across)).toBeLessThan(0.15);
    // The long cells across the wind, the short ones along it.
    const alongScale = Math.hypot(lattice.axes[0], lattice.axes[1]);
    const acrossScale = Math.hypot(lattice.axes[2], lattice.axes[3]);
    const crosswise: WindrowLattice = { ...lattice, axes: [-wz * alongScale, wx * alongScale, wx * acrossScale, wz * acrossScale] };
    expect(correlationAt(crosswise, wx, wz, 12)).toBeLessThan(0.15);
  });

  it('are carried with the surface’s drift, and read the same far from the world’s origin through the split lattice', () => {
    const seed = 11;
    const [vx, vz] = foamDriftVelocity(SEA);
    const t = 1234.5;
    // A render origin 10⁶ m out: whole cells in the integers, the rest small.
    const origin: [number, number] = [1.0e6 + 3.3, -2.0e6 + 0.7];
    const later = windrowLattice(SEA, origin[0], origin[1], t);
    const start = windrowLattice(SEA, 0, 0, 0);
    for (const [x, z] of [
      [1.0e6 + 10, -2.0e6 - 4],
      [1.0e6 - 31.5, -2.0e6 + 17.25],
    ]) {
      const carried = shareAt(later, origin[0], origin[1], x + vx * t, z + vz * t, seed);
      expect(carried).toBeCloseTo(shareAt(start, 0, 0, x, z, seed), 6);
    }
    expect(Math.abs(later.offset[0]) + Math.abs(later.offset[1])).toBeLessThan(2);
  });
});
