import { followStep, type FollowerState } from './dampedFollower';
import { forwardOf, targetPose, type BoatPose, type HeightAt, type HullSize } from './boatPose';

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

export interface BoatMotionState {
  pose: BoatPose;
  /** The undamped pose on the surface at this instant, for comparison. */
  target: BoatPose;
}

const clampToExtent = (v: number) => Math.min(BOAT_EXTENT, Math.max(-BOAT_EXTENT, v));
const TWO_PI = 2 * Math.PI;
/** The angle in [−π, π) equal to `angle` modulo 2π. */
const wrapSigned = (angle: number) => angle - TWO_PI * Math.floor((angle + Math.PI) / TWO_PI);

/**
 * The boat over time: sails along its heading at its speed, kept within BOAT_EXTENT, and
 * floats: heave, pitch and roll follow the surface's pose through critically damped
 * springs, and the hull swings round to a new heading the same way, the short way round.
 * Time comes in from the frame loop's clock. A step of zero (a frozen or paused
 * clock), a step back, or the first update puts the boat exactly on its target pose, so a
 * still picture always shows the true pose of that instant; a step longer than `maxStep`
 * (a jump with setTime) does the same instead of sailing the whole gap.
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

  constructor(
    start: readonly [number, number] = BOAT_START,
    private readonly maxStep = 0.1,
  ) {
    this.x = clampToExtent(start[0]);
    this.z = clampToExtent(start[1]);
  }

  update(time: number, controls: BoatControls, hull: HullSize, heightAt: HeightAt): BoatMotionState {
    const dt = this.lastTime === null ? NaN : time - this.lastTime;
    this.lastTime = time;
    const stepping = dt > 0 && dt <= this.maxStep;
    if (stepping) {
      const commanded = this.heading.value + wrapSigned(controls.heading - this.heading.value);
      this.heading = followStep(this.heading, commanded, dt, 1 / HEADING_RESPONSE, HEADING_BAND);
      const [fx, fz] = forwardOf(this.heading.value);
      this.x = clampToExtent(this.x + fx * controls.speed * dt);
      this.z = clampToExtent(this.z + fz * controls.speed * dt);
    } else {
      this.heading = { value: controls.heading, velocity: 0 };
    }
    const heading = this.heading.value - TWO_PI * Math.floor(this.heading.value / TWO_PI);
    const target = targetPose(heightAt, this.x, this.z, heading, hull);
    if (stepping) {
      const omega = 1 / controls.response;
      this.heave = followStep(this.heave, target.y, dt, omega, HEAVE_BAND);
      this.pitch = followStep(this.pitch, target.pitch, dt, omega, ANGLE_BAND);
      this.roll = followStep(this.roll, target.roll, dt, omega, ANGLE_BAND);
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

  state(): BoatMotionState | null {
    return this.current;
  }
}
