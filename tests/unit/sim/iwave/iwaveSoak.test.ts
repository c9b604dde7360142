import { describe, expect, it } from 'vitest';
import { GRAVITY, IWAVE_SPONGE, IWaveGrid } from '../../../../src/sim/iwave/iwaveGrid';
import { fittedVerticalDerivativeKernel } from '../../../../src/sim/iwave/verticalDerivativeKernel';
import { IWAVE_DAMPING, IWAVE_SPACING, IWAVE_STEP } from '../../../../src/sim/iwave/fieldSize';
import { hullEarlier, type MovingHull } from '../../../../src/sim/iwave/movingHull';

/**
 * No blow-up: the interactive field with the app's kernel, sponge, damping and step, driven by
 * steady sources (the boat circling at 4 m/s, pushing water, and a stone every 2 s), keeps its
 * energy bounded, and once the sources stop the energy falls away. The CPU solver, which the
 * GPU one matches to 1e-4 (tests/browser/iwaveParity.test.ts). Ten minutes of simulated time
 * on a 128² grid with IWAVE_SOAK_FULL=1 (`npm run soak:iwave`); one minute on 64² here.
 */
const full = process.env.IWAVE_SOAK_FULL === '1';
const n = full ? 128 : 64;
const drivenSeconds = full ? 600 : 60;
// Long enough for the waves in the field to reach the sponge: the shortest it carries (4.2 rad/m)
// run at 0.76 m/s, so the time grows with the grid's width.
const quietSeconds = 30 * (n / 64);

/**
 * The quadratic quantity ∂²h/∂t² = −g √(−∇²) h keeps, m⁴/s²: ½ Σ ((h − h⁻)/Δt)² Δx² plus
 * ½ Σ (g/Δx) h (G ∗ h) Δx² (the kernel's response is positive, so both terms are). Damping,
 * the sponge and the sources change it; nothing else does.
 */
function energy(grid: IWaveGrid, dt: number): number {
  const convolved = new Float64Array(grid.height.length);
  grid.convolve(grid.height, convolved);
  let sum = 0;
  for (let c = 0; c < grid.height.length; c++) {
    const velocity = (grid.height[c] - grid.previous[c]) / dt;
    sum += velocity * velocity + (GRAVITY / grid.spacing) * grid.height[c] * convolved[c];
  }
  return 0.5 * sum * grid.spacing * grid.spacing;
}

describe('the interactive field over a long run', () => {
  it(
    `keeps its energy bounded for ${drivenSeconds} s of steady sources, and loses it once they stop`,
    () => {
      const grid = new IWaveGrid({
        n,
        spacing: IWAVE_SPACING,
        kernel: fittedVerticalDerivativeKernel(),
        damping: IWAVE_DAMPING,
        sponge: IWAVE_SPONGE,
      });
      // The boat on a circle of radius 8 m round the centre: 4 m/s, turning 0.5 rad/s.
      const turnRate = 0.5;
      const start: MovingHull = { x: -8, z: 0, heading: 0, speed: 4, length: 8, beam: 2.6, strength: 1 };
      const windows: number[] = [];
      let windowSum = 0;
      let windowCount = 0;
      const stepsPerWindow = Math.round(10 / IWAVE_STEP);
      const total = Math.round((drivenSeconds + quietSeconds) / IWAVE_STEP);
      const driven = Math.round(drivenSeconds / IWAVE_STEP);
      let atStop = 0;
      let largest = 0;
      for (let s = 1; s <= total; s++) {
        const t = s * IWAVE_STEP;
        grid.hull = s <= driven ? hullEarlier(start, turnRate, -t) : null;
        grid.step(IWAVE_STEP);
        if (s <= driven && s % 120 === 0) grid.disturb({ x: ((s / 120) % 2 === 0 ? -1 : 1) * 6, z: 5, radius: 1, height: 0.4 });
        if (s % 6 === 0) {
          const e = energy(grid, IWAVE_STEP);
          expect(Number.isFinite(e)).toBe(true);
          largest = Math.max(largest, e);
          windowSum += e;
          windowCount++;
        }
        if (s % stepsPerWindow === 0) {
          windows.push(windowSum / windowCount);
          windowSum = 0;
          windowCount = 0;
        }
        if (s === driven) atStop = energy(grid, IWAVE_STEP);
      }
      const drivenWindows = windows.slice(0, drivenSeconds / 10);
      const settled = drivenWindows.slice(3);
      console.log(
        `iWave ${n}², ${drivenSeconds} s driven: energy per 10 s window ${drivenWindows.map((e) => e.toFixed(3)).join(', ')} m⁴/s²; largest ${largest.toFixed(3)}; at the stop ${atStop.toFixed(3)}, ${quietSeconds} s later ${windows.at(-1)!.toFixed(4)}`,
      );
      // Bounded: once the sources have run 30 s, no window holds twice the middle one (a stone that
      // falls into the bow wave makes a spike), and the last third of them no more than the first
      // third give or take a quarter: a blow-up grows without end.
      const sorted = [...settled].sort((a, b) => a - b);
      const median = sorted[Math.floor(sorted.length / 2)];
      for (const e of settled) expect(e).toBeLessThan(2 * median);
      const third = Math.max(1, Math.floor(settled.length / 3));
      const mean = (list: number[]) => list.reduce((a, b) => a + b, 0) / list.length;
      expect(mean(settled.slice(-third))).toBeLessThan(1.25 * mean(settled.slice(0, third)));
      // Decaying: the last quiet window holds under a tenth of the energy at the stop.
      expect(windows.at(-1)!).toBeLessThan(0.1 * atStop);
    },
    full ? 3_600_000 : 300_000,
  );
});
