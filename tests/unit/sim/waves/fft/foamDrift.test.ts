import { describe, expect, it } from 'vitest';
import {
  driftedMemoryStep,
  foamDriftStep,
  foamDriftTexels,
  foamDriftVelocity,
  WIND_DRIFT_SHARE,
} from '../../../../../src/sim/waves/fft/foamDrift';
import { FOAM_POTENTIAL_MAX, FOAM_STEP_SECONDS, foamSteps } from '../../../../../src/sim/waves/fft/foamMemory';
import { foamRemaining } from '../../../../../src/sim/waves/fft/whitecaps';
import { seededRandom } from '../../../../../src/sim/noise/integerHash';

const N = 32;
const TEXEL = 0.13;

/** Seeded fresh potentials at lattice step k: a few folds over the tile. */
function freshAt(k: number): Float32Array {
  const random = seededRandom(5000 + k);
  return Float32Array.from({ length: N * N }, () => {
    const r = random();
    return r < 0.97 ? 0 : (FOAM_POTENTIAL_MAX * (r - 0.97)) / 0.03;
  });
}

/**
 * The memory a frame loop leaves at the last frame: each frame steps what foamSteps asks, each
 * step drifted by its own lattice shift; or (`perFrame`, the control) undrifted steps and then
 * the frame's own drift, rounded to texels.
 */
function memoryAfter(frameTimes: readonly number[], tau: number, velocity: [number, number], perFrame = false): Float32Array {
  let memory: Float32Array = new Float32Array(N * N);
  let done: number | null = null;
  let previousTime = frameTimes[0];
  for (const time of frameTimes) {
    const steps = foamSteps(done, time, tau);
    if (steps.fresh) memory = new Float32Array(N * N);
    for (let k = steps.first; k <= steps.last; k++) {
      const decay = k === steps.first && steps.fresh ? 0 : foamRemaining(FOAM_STEP_SECONDS, tau);
      memory = driftedMemoryStep(memory, freshAt(k), N, decay, perFrame ? [0, 0] : foamDriftStep(velocity, TEXEL, k));
    }
    if (perFrame) {
      const frameShift = velocity.map((v) => Math.round((v * (time - previousTime)) / TEXEL)) as [number, number];
      memory = driftedMemoryStep(memory, new Float32Array(N * N), N, 1, frameShift);
    }
    previousTime = time;
    done = steps.last;
  }
  return memory;
}

describe('the foam left behind drifts with the surface (src/sim/waves/fft/foamDrift.ts)', () => {
  it('downwind at 3 % of U10 (AMS Glossary, "wind drift"): 0.3 m/s at 10 m/s, wind towards +x at 90°', () => {
    expect(WIND_DRIFT_SHARE).toBe(0.03);
    const [vx, vz] = foamDriftVelocity({ windSpeed: 10, windDirection: 90 });
    expect(vx).toBeCloseTo(0.3, 12);
    expect(vz).toBeCloseTo(0, 12);
    expect(Math.hypot(...foamDriftVelocity({ windSpeed: 20, windDirection: 33 }))).toBeCloseTo(0.6, 12);
  });

  it('moves by whole texels whose sum over the steps is the drift to the nearest texel, at every step', () => {
    const velocity: [number, number] = [0.31, -0.17];
    let sum = [0, 0];
    for (let k = 1; k <= 2000; k++) {
      const [dx, dz] = foamDriftStep(velocity, TEXEL, k);
      sum = [sum[0] + dx, sum[1] + dz];
      const metres = k * FOAM_STEP_SECONDS;
      expect(Math.abs(sum[0] * TEXEL - velocity[0] * metres)).toBeLessThanOrEqual(TEXEL / 2 + 1e-9);
      expect(Math.abs(sum[1] * TEXEL - velocity[1] * metres)).toBeLessThanOrEqual(TEXEL / 2 + 1e-9);
    }
    expect(foamDriftTexels(velocity, TEXEL, 2000)).toEqual(sum);
  });

  it('carries a patch of foam v t downwind while it fades by e^{−t/τ}', () => {
    const previous = new Float32Array(N * N);
    previous[10 * N + 4] = FOAM_POTENTIAL_MAX;
    const velocity: [number, number] = [0.6, 0];
    let memory: Float32Array = previous;
    const steps = 10;
    for (let k = 1; k <= steps; k++)
      memory = driftedMemoryStep(
        memory,
        new Float32Array(N * N),
        N,
        foamRemaining(FOAM_STEP_SECONDS, 2.5),
        foamDriftStep(velocity, TEXEL, k),
      );
    const at = memory.findIndex((p) => p > 0);
    const moved = (at % N) - 4;
    expect(Math.abs(moved * TEXEL - velocity[0] * steps * FOAM_STEP_SECONDS)).toBeLessThanOrEqual(TEXEL / 2);
    expect(Math.floor(at / N)).toBe(10);
    expect(memory[at]).toBeCloseTo(FOAM_POTENTIAL_MAX * Math.exp(-1 / 2.5), 5);
  });

  // Control: a drift by each frame’s own time step differs.
  it('leaves the same memory, to the bit, played at 60 or 23 fps or jumped to', () => {
    const velocity = foamDriftVelocity({ windSpeed: 20, windDirection: 57 });
    const end = 13.37;
    const played = (fps: number) => Array.from({ length: Math.floor((end - 6) * fps) }, (_, i) => 6 + i / fps).concat([end]);
    const jumped = memoryAfter([end], 2.5, velocity);
    expect(jumped.some((p) => p > 0)).toBe(true);
    expect(memoryAfter(played(60), 2.5, velocity)).toEqual(jumped);
    expect(memoryAfter(played(23), 2.5, velocity)).toEqual(jumped);
    // Control: the drift applied per frame, by the frame's own time step rounded to texels, is
    // 0.077 texel at 60 fps, so the foam stays put, unlike the jump's.
    expect(memoryAfter(played(60), 2.5, velocity, true)).not.toEqual(jumped);
  });
});
