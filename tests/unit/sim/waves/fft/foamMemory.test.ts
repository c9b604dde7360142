import { describe, expect, it } from 'vitest';
import {
  FOAM_POTENTIAL_MAX,
  FOAM_STEP_SECONDS,
  foamLatticeIndex,
  foamMemorySeconds,
  foamSteps,
  rememberFoam,
} from '../../../../../src/sim/waves/fft/foamMemory';
import { foamRemaining } from '../../../../../src/sim/waves/fft/whitecaps';
import { seededRandom } from '../../../../../src/sim/noise/integerHash';

/** One texel's fresh potential at lattice index k: seeded, a fold now and then (values 0–3). */
function freshAt(k: number): number {
  const r = seededRandom(1000 + k)();
  return r < 0.7 ? 0 : (FOAM_POTENTIAL_MAX * (r - 0.7)) / 0.3;
}

/** A texel's memory driven by a frame loop: each frame asks foamSteps, steps those indices, draws memory × fade. */
function drawnAt(frameTimes: readonly number[], tau: number): number {
  let memory = 0;
  let done: number | null = null;
  let drawn = 0;
  for (const time of frameTimes) {
    const steps = foamSteps(done, time, tau);
    if (steps.fresh) memory = 0;
    for (let k = steps.first; k <= steps.last; k++)
      memory = rememberFoam(memory, freshAt(k), k === steps.first && steps.fresh ? 0 : foamRemaining(FOAM_STEP_SECONDS, tau));
    done = steps.last;
    drawn = memory * steps.fade;
  }
  return drawn;
}

/** The old scheme: faded by e^{−Δt/τ} per frame, fresh foam from each frame's own time. */
function perFrame(frameTimes: readonly number[], tau: number): number {
  let memory = 0;
  let previous = frameTimes[0];
  for (const time of frameTimes) {
    memory = Math.max(memory * foamRemaining(time - previous, tau), freshAt(foamLatticeIndex(time)) * (0.9 + 0.1 * Math.sin(time * 37)));
    previous = time;
  }
  return memory;
}

describe('foam remembered on a lattice of simulation times', () => {
  // τ = 0.5, 2.5, 8 s, 40 end times (control: a per-frame fade differs).
  it('draws the same at t whether played at 60 or 23 fps, stepped by 1/60 s, or jumped to', () => {
    const random = seededRandom(77);
    let controlDiffers = 0;
    for (const tau of [0.5, 2.5, 8]) {
      for (let trial = 0; trial < 40; trial++) {
        const end = 20 + 30 * random();
        const played = (fps: number) => Array.from({ length: Math.floor((end - 5) * fps) }, (_, i) => 5 + i / fps).concat([end]);
        const jumped = drawnAt([end], tau);
        expect(drawnAt(played(60), tau)).toBe(jumped);
        expect(drawnAt(played(23), tau)).toBe(jumped);
        if (perFrame(played(60), tau) !== perFrame(played(23), tau)) controlDiffers++;
      }
    }
    expect(controlDiffers).toBeGreaterThan(60);
  });

  it('a jump replays only the window the memory reaches: τ ln(3) plus a step', () => {
    expect(foamMemorySeconds(2.5)).toBeCloseTo(2.5 * Math.log(3), 12);
    const steps = foamSteps(null, 10, 2.5);
    expect(steps.fresh).toBe(true);
    expect(steps.last).toBe(100);
    expect(steps.last - steps.first).toBe(Math.ceil(foamMemorySeconds(2.5) / FOAM_STEP_SECONDS) + 1);
    const next = foamSteps(100, 10.25, 2.5);
    expect([next.first, next.last, next.fresh]).toEqual([101, 102, false]);
    expect(next.fade).toBeCloseTo(foamRemaining(0.05, 2.5), 12);
    // A lattice time computed in float (0.3 / 0.1 = 2.9999…) counts as reached.
    expect(foamLatticeIndex(0.3)).toBe(3);
  });

  it('forgets a potential once it fades below sight, and keeps the larger of the faded and the fresh', () => {
    expect(rememberFoam(2, 0, 0.4)).toBe(0);
    expect(rememberFoam(2, 0, 0.6)).toBeCloseTo(1.2, 12);
    expect(rememberFoam(2, 1.5, 0.6)).toBe(1.5);
  });
});
