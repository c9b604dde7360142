import { followStep, type FollowerState } from './dampedFollower';
import { forwardOf, targetPose, type BoatPose, type HeightAt, type HullSize } from './boatPose';
import type { SailLimit } from '../coast/aground';

/** Half side, metres, of the square around the origin the boat may sail in: inside the ocean's extent. */
export const BOAT_EXTENT = 2000;
/** Farthest the damped heave may stray from the surface at the hull's centre, metres. */
export const HEAVE_BAND = 0.2;
/** Farthest the damped pitch and roll may stray from the surface's, radians (≈ 4.6°). */
export const ANGLE_BAND = 0.08;
/** Farthest the boat's heading may lag the commanded one, radians: a turn through the GUI swings, not snaps. */
export const HEADING_BAND = Math.PI;
/** Response time of the heading, seconds: a hull turns slower than it heaves. */
export const HEADING_RESPONSE = 0.6;
/** Where the boat starts: in the default camera's view, right of centre. */
export const BOAT_START: readonly [number, number] = [7, -5];

export interface BoatControls {
  /** radians, see boatPose.ts for the convention */
  heading: number;
  /** m/s along the heading; negative goes astern */
  speed: number;
  /** response time of the floating motion, seconds */
  response: number;
}

/**
 * Everything the motion carries from frame to frame: with the time it was taken at, it
 * rebuilds the boat exactly (a share link carries it, so the boat comes back where it was,
 * with its damped heave, pitch and roll, not at its start or on its undamped pose).
 */
export interface BoatSnapshot {
  x: number;
  z: number;
  heading: FollowerState;
  heave: FollowerState;
  pitch: FollowerState;
  roll: FollowerState;
}

export interface BoatMotionState {
  pose: BoatPose;
  /** The undamped pose on the surface at this instant, for comparison. */
  target: BoatPose;
}

/**
 * Which surface `heightAt` reads, for keeping the target pose of a paused view: the wave model
 * itself (compared by identity) with its surface revision (LiveWaveModel.surfaceRevision, read
 * after the heights were taken, since taking them may compute the model's data). The same
 * model and revision at the same time answer every height alike.
 */
export interface SurfaceKey {
  readonly surfaceRevision: number;
}

/** What the last target pose was taken from. */
interface TargetKey {
  time: number;
  x: number;
  z: number;
  heading: number;
  length: number;
  beam: number;
  model: object;
  revision: number;
}

const clampTo = (state: FollowerState, target: number, band: number): FollowerState =>
  state.value > target + band
    ? { value: target + band, velocity: 0 }
    : state.value < target - band
      ? { value: target - band, velocity: 0 }
      : state;
const clampToExtent = (v: number) => Math.min(BOAT_EXTENT, Math.max(-BOAT_EXTENT, v));
const TWO_PI = 2 * Math.PI;
/** The angle in [−π, π) equal to `angle` modulo 2π. */
const wrapSigned = (angle: number) => angle - TWO_PI * Math.floor((angle + Math.PI) / TWO_PI);

/**
 * The boat over time: sails along its heading at its speed, kept within BOAT_EXTENT, and
 * floats: heave, pitch and roll follow the surface's pose through critically damped
 * springs, and the hull swings round to a new heading the same way, the short way round.
 * Time comes in from the frame loop's clock. The first update, a step back, or a step
 * longer than `maxStep` (a jump with setTime) puts the boat exactly on its target pose, so
 * a frozen link without a boat state shows the true pose of that instant. A step of zero
 * (a paused view drawn again) holds the springs where they were, so pausing freezes the
 * boat as it was and a share link made then (snapshot/restore) reproduces it; unless the
 * commanded heading changed since the last update (the GUI or the API steered a paused
 * view), which puts the boat at once on its true pose for the new heading.
 */
export class BoatMotion {
  private x: number;
  private z: number;
  private lastTime: number | null = null;
  private heave: FollowerState = { value: 0, velocity: 0 };
  private pitch: FollowerState = { value: 0, velocity: 0 };
  private roll: FollowerState = { value: 0, velocity: 0 };
  /** Unwrapped, so the spring turns the short way round; reported in [0, 2π). */
  private heading: FollowerState = { value: 0, velocity: 0 };
  private current: BoatMotionState | null = null;
  /** The heading commanded at the last update; null after a restore, which does not know it. */
  private command: number | null = null;
  /** The last target pose and what it was taken from (only when update was given a SurfaceKey). */
  private targetKey: TargetKey | null = null;
  private lastTarget: BoatPose | null = null;
  /** Where the boat may sail on a coast (sailUntilAground, src/sim/coast/aground.ts); null on the open sea. */
  limit: SailLimit | null = null;
  /** Whether the last step ran the boat aground (it stopped there). */
  aground = false;

  constructor(
    start: readonly [number, number] = BOAT_START,
    // Longer than any step the frame loop's clock takes (at most 0.1 s a frame,
    // src/app/time/simulationClock.ts), with room for float64 sums of those steps, so every
    // drawn frame sails however slow the renderer; only a jump with setTime is longer.
    private readonly maxStep = 0.25,
  ) {
    this.x = clampToExtent(start[0]);
    this.z = clampToExtent(start[1]);
  }

  /**
   * `surface`, where given, says which surface `heightAt` reads: a paused view drawn again
   * (same time, place, heading, hull and surface) keeps the last target pose instead of
   * sampling the surface five times again. `around`, where given, is the surface for a hull
   * at (x, z, heading), read in place of `heightAt` (water that the hull itself changes: the
   * interactive waves, held at 0 under it), and never kept.
   */
  update(
    time: number,
    controls: BoatControls,
    hull: HullSize,
    heightAt: HeightAt,
    surface?: SurfaceKey,
    around?: (x: number, z: number, heading: number) => HeightAt,
  ): BoatMotionState {
    const dt = this.lastTime === null ? NaN : time - this.lastTime;
    this.lastTime = time;
    const stepping = dt > 0 && dt <= this.maxStep;
    // The clock stood still (a paused view drawn again): the springs stand still too, kept
    // within their bands of a target that parameters may have moved; a new heading is the
    // user turning the boat, shown at once as before.
    const steeredStill = this.command !== null && controls.heading !== this.command;
    const holding = dt === 0 && this.current !== null && !steeredStill;
    this.command = controls.heading;
    if (stepping) {
      const commanded = this.heading.value + wrapSigned(controls.heading - this.heading.value);
      this.heading = followStep(this.heading, commanded, dt, 1 / HEADING_RESPONSE, HEADING_BAND);
      const [fx, fz] = forwardOf(this.heading.value);
      const next: [number, number] = [clampToExtent(this.x + fx * controls.speed * dt), clampToExtent(this.z + fz * controls.speed * dt)];
      const sailed = this.limit ? this.limit([this.x, this.z], next) : null;
      this.x = sailed ? sailed.x : next[0];
      this.z = sailed ? sailed.z : next[1];
      this.aground = sailed?.stopped ?? false;
    } else if (!holding) {
      this.heading = { value: controls.heading, velocity: 0 };
    }
    const heading = this.heading.value - TWO_PI * Math.floor(this.heading.value / TWO_PI);
    const target = around
      ? targetPose(around(this.x, this.z, heading), this.x, this.z, heading, hull)
      : this.targetAt(time, heading, hull, heightAt, surface);
    if (stepping) {
      const omega = 1 / controls.response;
      this.heave = followStep(this.heave, target.y, dt, omega, HEAVE_BAND);
      this.pitch = followStep(this.pitch, target.pitch, dt, omega, ANGLE_BAND);
      this.roll = followStep(this.roll, target.roll, dt, omega, ANGLE_BAND);
    } else if (holding) {
      this.heave = clampTo(this.heave, target.y, HEAVE_BAND);
      this.pitch = clampTo(this.pitch, target.pitch, ANGLE_BAND);
      this.roll = clampTo(this.roll, target.roll, ANGLE_BAND);
    } else {
      this.heave = { value: target.y, velocity: 0 };
      this.pitch = { value: target.pitch, velocity: 0 };
      this.roll = { value: target.roll, velocity: 0 };
    }
    this.current = {
      pose: { ...target, y: this.heave.value, pitch: this.pitch.value, roll: this.roll.value },
      target,
    };
    return this.current;
  }

  private targetAt(time: number, heading: number, hull: HullSize, heightAt: HeightAt, surface?: SurfaceKey): BoatPose {
    const k = this.targetKey;
    if (
      surface &&
      this.lastTarget &&
      k &&
      k.time === time &&
      k.x === this.x &&
      k.z === this.z &&
      k.heading === heading &&
      k.length === hull.length &&
      k.beam === hull.beam &&
      k.model === surface &&
      k.revision === surface.surfaceRevision
    ) {
      return this.lastTarget;
    }
    const target = targetPose(heightAt, this.x, this.z, heading, hull);
    this.lastTarget = target;
    this.targetKey = surface
      ? { time, x: this.x, z: this.z, heading, length: hull.length, beam: hull.beam, model: surface, revision: surface.surfaceRevision }
      : null;
    return target;
  }

  state(): BoatMotionState | null {
    return this.current;
  }

  /** The state at `time`, or null when the motion was last updated at another time (or never). */
  snapshot(time: number): BoatSnapshot | null {
    if (this.lastTime !== time || this.current === null) return null;
    return {
      x: this.x,
      z: this.z,
      heading: { ...this.heading },
      heave: { ...this.heave },
      pitch: { ...this.pitch },
      roll: { ...this.roll },
    };
  }

  /** Puts the boat back as `snapshot` had it at `time`: the next update at that time draws that very pose. */
  restore(snapshot: BoatSnapshot, time: number): void {
    this.x = clampToExtent(snapshot.x);
    this.z = clampToExtent(snapshot.z);
    this.heading = { ...snapshot.heading };
    this.heave = { ...snapshot.heave };
    this.pitch = { ...snapshot.pitch };
    this.roll = { ...snapshot.roll };
    this.lastTime = time;
    this.command = null;
    // Marks the motion as under way, so the first update holds the restored springs.
    this.current = {
      pose: { x: this.x, y: this.heave.value, z: this.z, heading: this.heading.value, pitch: this.pitch.value, roll: this.roll.value },
      target: { x: this.x, y: this.heave.value, z: this.z, heading: this.heading.value, pitch: this.pitch.value, roll: this.roll.value },
    };
  }
}
