import { foamRemaining } from './whitecaps';

/**
 * The foam the sea leaves behind, remembered on a fixed lattice of simulation times
 * t_k = k Δ, never per frame: at each t_k the remembered potential becomes
 * max(P_{k−1} e^{−Δ/τ}, fresh(t_k)), and a frame at time t draws P_k e^{−(t − t_k)/τ} for the
 * last t_k ≤ t. So what is drawn at t depends on t alone: playing at any frame rate, stepping
 * frame by frame and jumping straight to t draw the same foam.
 *
 * A jump need not replay all of history: a potential is at most FOAM_POTENTIAL_MAX, and one
 * that has faded below FOAM_POTENTIAL_VISIBLE is forgotten (set to 0, rememberFoam), so
 * anything deposited more than τ ln(max / visible) ago is gone whatever it was. A jump
 * replays the lattice times of that window only, from nothing: every potential still
 * remembered went through the same multiplications on both paths, so the memory is the same
 * to the bit (the pixels read it filtered, and a faint remnant kept on one path only would
 * have shown between texels).
 */
export const FOAM_STEP_SECONDS = 0.1;
/** Fresh foam's potential: 1 at the breaking threshold, growing into the fold, capped here. */
export const FOAM_POTENTIAL_MAX = 3;
/** Remembered foam is drawn from this potential up (fully at one more). */
export const FOAM_POTENTIAL_VISIBLE = 1;

/** One lattice step of one texel (GLSL twin: shaders/fftFoamMemory.frag): the older foam faded by `decay` or the fresh, the larger, forgotten below sight. */
export function rememberFoam(old: number, fresh: number, decay: number): number {
  const potential = Math.max(old * decay, fresh);
  return potential < FOAM_POTENTIAL_VISIBLE ? 0 : potential;
}

/** How far back a remembered potential can still be seen, seconds. */
export function foamMemorySeconds(fadeSeconds: number): number {
  return fadeSeconds * Math.log(FOAM_POTENTIAL_MAX / FOAM_POTENTIAL_VISIBLE);
}

/** The last lattice index whose time is not after `time` (a time on the lattice, k Δ computed in float, counts as reached). */
export function foamLatticeIndex(time: number): number {
  return Math.floor(time / FOAM_STEP_SECONDS + 1e-9);
}

export interface FoamSteps {
  /** Lattice indices to step, first to last inclusive (none when first > last). */
  first: number;
  last: number;
  /** Whether the memory starts from nothing at `first` (a jump, or the first frame). */
  fresh: boolean;
  /** The fade from the last stepped lattice time to `time`: e^{−(t − t_last)/τ}. */
  fade: number;
}

/**
 * The lattice steps that bring a memory last stepped at index `done` (null: never) to `time`:
 * the indices after `done`, or, after a jump back or further than the memory reaches, the
 * window's worth from nothing.
 */
export function foamSteps(done: number | null, time: number, fadeSeconds: number): FoamSteps {
  const last = foamLatticeIndex(time);
  // One step more than the memory's reach, so a potential at the cap is below sight at the window's far end even if it is a whole number of steps.
  const window = Math.ceil(foamMemorySeconds(fadeSeconds) / FOAM_STEP_SECONDS) + 1;
  const fade = foamRemaining(Math.max(0, time - last * FOAM_STEP_SECONDS), fadeSeconds);
  if (done !== null && done <= last && last - done <= window) return { first: done + 1, last, fresh: false, fade };
  return { first: last - window, last, fresh: true, fade };
}
