import { forwardOf } from '../boat/boatPose';
import { GRAVITY, historyWeight, type WakeParams } from './kelvinWake';
import type { SurfaceSample } from '../waves/waveModel';
import { TRACK_MAX_GAP, WakeTrack } from './wakeTrack';
import { packWakeUniforms, wakeAtWorld, type WakeUniformData } from './wakeUniformData';

/**
 * The boat's wake as the app keeps it: the recorded track (src/sim/wake/wakeTrack.ts), the
 * uniforms packed from it for a time, the culling bound, and the CPU twin's sum of the active
 * wave model and the wake (what sampleSurface answers; the boat itself floats on the waves
 * without its own wake).
 *
 * Deterministic: a track that starts afresh (the first frame, a jump in time, a frozen link
 * or preset) is not left empty but replayed: the boat is taken to have sailed with its
 * present controls (speed, turn rate) for the whole memory of the track up to where it is
 * now. The replay depends on the time, the boat's pose and the parameters only, so a frozen
 * t, a share link and a preset all give the same picture; from then on every frame records
 * the boat's real motion (steering included) at the track's fixed instants.
 */

/** The hull the wake is made for: the shipped model's (8 m × 2.6 m); fixed, so the wake does not change when the model finishes loading. */
export const WAKE_HULL = { length: 8, beam: 2.6 } as const;
/** Seconds of sailing a replay lays down: a little more than the track holds (78 s) so it is full. */
export const REPLAY_SECONDS = 80;
/** Replay step, seconds: chords of a 6 °/s turn at 12 m/s then stray 1 mm from the arc. */
const REPLAY_STEP = 0.1;
/** The uniforms of a wake switched off: nothing to draw, and nothing the twin adds. */
const WAKE_OFF = packWakeUniforms([], 0, { strength: 0, hullLength: WAKE_HULL.length, gravity: GRAVITY }, WAKE_HULL.beam);

/** What the boat does at an instant: the inputs the wake is made from. */
export interface WakeControls {
  /** Boat centre, world metres. */
  x: number;
  z: number;
  /** Radians, the convention of src/sim/boat/boatPose.ts (clockwise from −z). */
  heading: number;
  /** m/s along the heading. */
  speed: number;
  /** Radians per second the heading is turning (the boatTurnRate parameter). */
  turnRate: number;
}

export interface WakeSettings {
  enabled: boolean;
  /** The wakeStrength parameter. */
  strength: number;
}

/**
 * Where a boat now at `c` was `age` seconds ago, had it sailed with these controls all
 * along: integrated backwards in steps of at most REPLAY_STEP (midpoint heading, exact on a
 * straight course, 1 mm on the tightest turn).
 */
export function replayedPosition(c: WakeControls, age: number): [number, number] {
  let x = c.x;
  let z = c.z;
  const steps = Math.max(1, Math.ceil(age / REPLAY_STEP - 1e-9));
  const h = age / steps;
  for (let i = 0; i < steps; i++) {
    const [fx, fz] = forwardOf(c.heading - c.turnRate * (i + 0.5) * h);
    x -= fx * c.speed * h;
    z -= fz * c.speed * h;
  }
  return [x, z];
}

/**
 * An upper bound on |η| anywhere, metres: each segment of the quadrature adds at most
 * |C| Δτ Ā (|sin · sinc| ≤ 1), and a source's amplitude τ³/r⁴ · exp(−k²σ²/4), k = gτ²/4r²,
 * is at most min(τ³/σ⁴, 64 / (e g² σ² τ)) over r ≥ σ (the second is the maximum of
 * u² exp(−a u²), u = 1/r², a = g²τ⁴σ²/64). Used to grow the chunks' culling boxes.
 */
export function wakeHeightBound(data: WakeUniformData): number {
  if (data.count < 2 || data.params[0] === 0) return 0;
  const c = Math.abs(data.params[0]);
  const sigma = data.params[1];
  const g = data.params[3];
  const peak = (tau: number) =>
    tau <= 0 ? 0 : Math.min(tau ** 3 / sigma ** 4, 64 / (Math.E * g * g * sigma * sigma * tau)) * historyWeight(tau);
  let sum = 0;
  for (let i = 1; i < data.count; i++) {
    const a = data.track[(i - 1) * 4 + 2];
    const b = data.track[i * 4 + 2];
    sum += 0.5 * (peak(a) + peak(b)) * (b - a);
  }
  return c * sum;
}

/**
 * The model's sample with the wake added at the same world point: heights add, and the
 * normal is tilted by the wake's slope, (n.x − ∂η/∂x · n.y, n.y, n.z − ∂η/∂z · n.y) normalised
 * (the normal of y = h_model + η, written from the model's unit normal). The GLSL does the same
 * (wakeTiltNormal in shaders/wake.glsl).
 */
export function addWake(sample: SurfaceSample, wake: readonly [number, number, number]): SurfaceSample {
  const [nx, ny, nz] = sample.normal;
  const x = nx - wake[1] * ny;
  const z = nz - wake[2] * ny;
  const length = Math.hypot(x, ny, z);
  return { height: sample.height + wake[0], normal: [x / length, ny / length, z / length] };
}

export class BoatWake {
  private trackState = new WakeTrack();
  /** The inputs of the last replay, while the clock has not moved on from it. */
  private replayed: (WakeControls & { time: number }) | null = null;
  private packed: { time: number; settings: WakeSettings; data: WakeUniformData } | null = null;

  get track(): WakeTrack {
    return this.trackState;
  }

  /** A share link's track (WakeTrack.parse): the wake continues from it rather than being replayed. */
  restore(track: WakeTrack): void {
    this.trackState = track;
    this.replayed = null;
    this.packed = null;
  }

  /** Records the boat at `time` (every frame); a fresh track is replayed first (see above). */
  record(time: number, c: WakeControls): void {
    const head = this.trackState.fine.latest();
    const r = this.replayed;
    const fresh = head === null || !(time >= head.time) || time - head.time > TRACK_MAX_GAP;
    // Paused on a replayed track and given new controls (a slider, the API): replay them, so
    // a frozen view shows the wake of what it now says the boat does.
    const changed =
      r !== null &&
      r.time === time &&
      (r.x !== c.x || r.z !== c.z || r.heading !== c.heading || r.speed !== c.speed || r.turnRate !== c.turnRate);
    if (fresh || changed) this.replay(time, c);
    // A paused view drawn again with the boat where it was: the track, and so the packed
    // uniforms, stand (recording would change nothing but cost the repacking).
    else if (head !== null && head.time === time && head.x === c.x && head.z === c.z && head.speed === c.speed) return;
    else if (time !== r?.time) this.replayed = null;
    this.trackState.record(time, c.x, c.z, c.speed);
    this.packed = null;
  }

  private replay(time: number, c: WakeControls): void {
    this.trackState.reset();
    const steps = Math.round(REPLAY_SECONDS / REPLAY_STEP);
    for (let i = steps; i > 0; i--) {
      const age = i * REPLAY_STEP;
      const [x, z] = replayedPosition(c, age);
      this.trackState.record(time - age, x, z, c.speed);
    }
    this.replayed = { ...c, time };
  }

  /** The uniforms of shaders/wake.glsl at `time` (cached per time and settings). */
  uniforms(time: number, settings: WakeSettings): WakeUniformData {
    // Off (the default), the shaders skip the wake and the twin adds nothing: no track to pack.
    if (!settings.enabled) return WAKE_OFF;
    const p = this.packed;
    if (p && p.time === time && p.settings.enabled === settings.enabled && p.settings.strength === settings.strength) return p.data;
    const data = packWakeUniforms(this.trackState.points(), time, this.params(settings), WAKE_HULL.beam);
    this.packed = { time, settings: { ...settings }, data };
    return data;
  }

  /** [η, ∂η/∂x, ∂η/∂z] at world (x, z) exactly as the GPU computes it from `uniforms(time, settings)`. */
  at(x: number, z: number, time: number, settings: WakeSettings): [number, number, number] {
    return wakeAtWorld(x, z, this.uniforms(time, settings), this.params(settings));
  }

  private params(settings: WakeSettings): WakeParams {
    return { strength: settings.enabled ? settings.strength : 0, hullLength: WAKE_HULL.length, gravity: GRAVITY };
  }
}
