import { describe, expect, it } from 'vitest';
import type { MessageError } from '../../../../src/sim/params/message';
import { checkDisturbance, IWAVE_SPACING, sampleField, type FieldSnapshot } from '../../../../src/sim/iwave/interactiveField';
import { IWaveGrid } from '../../../../src/sim/iwave/iwaveGrid';
import { fittedVerticalDerivativeKernel } from '../../../../src/sim/iwave/verticalDerivativeKernel';

describe('disturb() arguments', () => {
  it('throws a MessageError naming the argument for non-finite or out-of-range input, its notice a disturbInvalid', () => {
    expect(() => checkDisturbance(Number.NaN, 0)).toThrow(/x must be|z must be/);
    expect(() => checkDisturbance(0, Infinity)).toThrow(/x must be|z must be/);
    expect(() => checkDisturbance(0, 0, { radius: -1 })).toThrow(/radius/);
    expect(() => checkDisturbance(0, 0, { radius: 11 })).toThrow(/radius/);
    expect(() => checkDisturbance(0, 0, { height: 2.5 })).toThrow(/height/);
    expect(() => checkDisturbance(0, 0, { height: Number.NaN })).toThrow(/height/);
    expect(() => checkDisturbance(2e6, 0)).toThrow(/x must be/);
    const noticeOf = (call: () => unknown) => {
      try {
        call();
      } catch (error) {
        return (error as MessageError).notice;
      }
      return null;
    };
    expect(noticeOf(() => checkDisturbance(0, 0, { radius: 11 }))).toEqual({
      id: 'disturbInvalid',
      values: { name: 'radius', got: '11', min: 0, max: 10 },
    });
    expect(noticeOf(() => checkDisturbance(0, Number.NaN))).toEqual({
      id: 'disturbInvalid',
      values: { name: 'z', got: 'NaN', min: -1e6, max: 1e6 },
    });
  });

  it('raises a radius under one texel to one texel and says so; a fair one passes unchanged with no notice', () => {
    const small = checkDisturbance(1, 2, { radius: 0.1, height: 0.2 });
    expect(small.disturbance).toEqual({ x: 1, z: 2, radius: IWAVE_SPACING, height: 0.2 });
    expect(small.notices).toEqual([{ id: 'disturbRadiusRaised', values: { radius: 0.1, raised: IWAVE_SPACING } }]);
    const fair = checkDisturbance(1, 2, { radius: 1.5, height: -0.4 });
    expect(fair.disturbance).toEqual({ x: 1, z: 2, radius: 1.5, height: -0.4 });
    expect(fair.notices).toEqual([]);
  });
});

describe('sampling a read-back of the field (the CPU twin of shaders/iwave.glsl)', () => {
  const n = 64;
  const grid = new IWaveGrid({ n, spacing: IWAVE_SPACING, kernel: fittedVerticalDerivativeKernel(), sponge: { width: 8, strength: 3 } });
  grid.recentre(3.2, -7.9);
  grid.disturb({ x: 4, z: -8, radius: 1.5, height: 0.4 });
  for (let s = 0; s < 30; s++) grid.step(1 / 60);
  const snapshot: FieldSnapshot = {
    heights: Float32Array.from(grid.height),
    stride: 1,
    n,
    spacing: IWAVE_SPACING,
    centerX: grid.centerX,
    centerZ: grid.centerZ,
  };

  // Planted fault: a half-texel shift misses.
  it("gives the solver's bilinear height inside the square and its slope by central differences", () => {
    let worst = 0;
    let worstShifted = 0;
    for (const [x, z] of [
      [4.1, -7.7],
      [5.3, -9.2],
      [2.05, -6.4],
      [4, -8],
    ]) {
      const [h, dx, dz] = sampleField(snapshot, x, z);
      worst = Math.max(worst, Math.abs(h - grid.sample(x, z)));
      expect(dx).toBeCloseTo((grid.sample(x + 0.5, z) - grid.sample(x - 0.5, z)) / 1, 6);
      expect(dz).toBeCloseTo((grid.sample(x, z + 0.5) - grid.sample(x, z - 0.5)) / 1, 6);
      worstShifted = Math.max(
        worstShifted,
        Math.abs(sampleField({ ...snapshot, centerX: snapshot.centerX + 0.25 }, x, z)[0] - grid.sample(x, z)),
      );
    }
    expect(worst).toBeLessThan(1e-6);
    expect(worstShifted).toBeGreaterThan(1e-3);
  });

  it('fades to nothing over the outer tenth and is zero beyond', () => {
    const half = 0.5 * n * IWAVE_SPACING;
    const ones: FieldSnapshot = { ...snapshot, heights: new Float32Array(n * n).fill(1) };
    expect(sampleField(ones, snapshot.centerX + 0.5 * half, snapshot.centerZ)[0]).toBeCloseTo(1, 9);
    expect(sampleField(ones, snapshot.centerX + 0.95 * half, snapshot.centerZ)[0]).toBeCloseTo(0.5, 9);
    expect(sampleField(ones, snapshot.centerX, snapshot.centerZ - 1.01 * half)).toEqual([0, 0, 0]);
  });
});
