import { describe, expect, it } from 'vitest';
import { gerstnerDerivativesAt, gerstnerTimePhases, type GerstnerWave } from '../../../../../src/sim/waves/gerstner/gerstnerWaves';
import { gerstnerSea } from '../../../../../src/sim/waves/gerstner/gerstnerSpectrum';
import { gerstnerSlopeVariance, trochoidSlopeVariance } from '../../../../../src/sim/waves/gerstner/gerstnerSlopes';
import { cosineSquared, piersonMoskowitz } from '../../../../support/testSeas';

/**
 * A trochoid's mean-square slope over the sea's area, (Ak)² (1 − √(1 − q²)) / q², against the
 * curve itself: X = p − QA sin kp, Y = A cos kp drawn on a fine grid of p, slopes ΔY/ΔX
 * weighted by the length ΔX each step covers.
 */
function trochoidByCurve(amplitude: number, k: number, horizontal: number, steps = 200_000): number {
  let sum = 0;
  let length = 0;
  for (let i = 0; i < steps; i++) {
    const p0 = ((i / steps) * (2 * Math.PI)) / k;
    const p1 = (((i + 1) / steps) * (2 * Math.PI)) / k;
    const dx = p1 - horizontal * Math.sin(k * p1) - (p0 - horizontal * Math.sin(k * p0));
    const dy = amplitude * (Math.cos(k * p1) - Math.cos(k * p0));
    sum += (dy * dy) / dx;
    length += dx;
  }
  return sum / length;
}

describe('Gerstner’s resolved slopes', () => {
  it('a trochoid’s matches its curve at q = 0.01, 0.5, 0.9, 0.99; control: the sine wave’s (Ak)²/2 fails at q = 0.9', () => {
    const k = (2 * Math.PI) / 12;
    for (const q of [0.01, 0.5, 0.9, 0.99]) {
      const amplitude = 0.8 / k;
      const horizontal = q / k;
      expect(trochoidSlopeVariance(amplitude, k, horizontal) / trochoidByCurve(amplitude, k, horizontal)).toBeCloseTo(1, 3);
    }
    expect(trochoidSlopeVariance(0.5, k, 0)).toBeCloseTo((0.5 * k) ** 2 / 2, 12);
    const amplitude = 0.9 / k;
    expect(Math.abs((amplitude * k) ** 2 / 2 / trochoidByCurve(amplitude, k, 0.9 / k) - 1)).toBeGreaterThan(0.2);
  });

  /** tan² of the surface's tilt averaged over its area (each grid cell weighted by the area it becomes, det J). */
  function measuredOnSurface(waves: GerstnerWave[], extent: number): number {
    const phases = gerstnerTimePhases(waves, 4.2);
    let sum = 0;
    let area = 0;
    const n = 400;
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const d = gerstnerDerivativesAt(waves, phases, ((i + 0.3) * extent) / n, ((j + 0.7) * extent) / n);
        const tx = [1 + d.dxdx, d.dydx, d.dxdz];
        const tz = [d.dxdz, d.dydz, 1 + d.dzdz];
        const nx = tz[1] * tx[2] - tz[2] * tx[1];
        const ny = tz[2] * tx[0] - tz[0] * tx[2];
        const nz = tz[0] * tx[1] - tz[1] * tx[0];
        const jacobian = (1 + d.dxdx) * (1 + d.dzdz) - d.dxdz * d.dxdz;
        sum += ((nx * nx + nz * nz) / (ny * ny)) * jacobian;
        area += jacobian;
      }
    }
    return sum / area;
  }

  // Control: each wave’s peak slope squared, (Ak)², fails.
  it('a PM sea of 32 trochoids (Q = 1) has the sum of theirs, measured on its surface, within 3 %', () => {
    const waves = gerstnerSea({
      count: 32,
      seed: 7,
      spectrum: piersonMoskowitz(10).spectrum,
      spreading: cosineSquared,
      windDirection: 0.3,
      steepness: 1,
    });
    const surface = measuredOnSurface(waves, 600);
    expect(Math.abs(gerstnerSlopeVariance(waves) / surface - 1)).toBeLessThan(0.03);
    const peak = waves.reduce((sum, w) => sum + (w.amplitude * 2 * Math.PI * Math.hypot(w.cx, w.cz)) ** 2, 0);
    expect(Math.abs(peak / surface - 1)).toBeGreaterThan(0.5);
  });

  // Control: the sine waves’ (Ak)²/2, 2 % off, fails.
  it('4 steep trochoids (Σ QkA = 1, as gerstner-steepness) too, within 1 %', () => {
    const waves = gerstnerSea({
      count: 4,
      seed: 1,
      spectrum: piersonMoskowitz(20).spectrum,
      spreading: cosineSquared,
      windDirection: 0.3,
      steepness: 1,
    });
    const surface = measuredOnSurface(waves, 300);
    const error = Math.abs(gerstnerSlopeVariance(waves) / surface - 1);
    expect(error).toBeLessThan(0.01);
    const linear = gerstnerSlopeVariance(waves.map((w) => ({ ...w, horizontal: 0 })));
    expect(Math.abs(linear / surface - 1)).toBeGreaterThan(0.015);
  });
});
