import { GRAVITY } from '../wake/kelvinWake';

/** Metres over which the analytic wake takes over from the interactive field. */
export const HAND_OVER_WIDTH = 8;

/**
 * Where the interactive field hands the boat's waves over to the analytic Kelvin wake: the
 * wake's stationary-phase sum is a far field, right where the distance from the hull is large
 * against both the hull and the transverse wavelength 2πU²/g (Kelvin 1887; Lighthill, Waves in
 * Fluids, §3.10), so D = max(2 L, 2πU²/g).
 */
export function handOverDistance(speed: number, hullLength: number, gravity = GRAVITY): number {
  return Math.max(2 * hullLength, (2 * Math.PI * speed * speed) / gravity);
}

/**
 * The analytic wake's weight at `distance` metres from the boat: 0 within D, where the field
 * carries the boat's waves, rising to 1 at D + HAND_OVER_WIDTH (a smoothstep, as GLSL's). The
 * field is weighted by 1 − this around the boat, so each wave is counted once. The GLSL twin
 * is iwaveWakeWeight in shaders/iwave.glsl.
 */
export function analyticWakeWeight(distance: number, handOver: number): number {
  const t = Math.min(1, Math.max(0, (distance - handOver) / HAND_OVER_WIDTH));
  return t * t * (3 - 2 * t);
}

/** Where the blend stands this frame: the boat's position and D, or null while no hand-over applies (the wake off, or no field). */
export interface HandOver {
  x: number;
  z: number;
  distance: number;
}

/** The weights (analytic wake, interactive field) at world (x, z): both 1 without a hand-over. */
export function handOverWeights(handOver: HandOver | null, x: number, z: number): [wake: number, field: number] {
  if (!handOver) return [1, 1];
  const w = analyticWakeWeight(Math.hypot(x - handOver.x, z - handOver.z), handOver.distance);
  return [w, 1 - w];
}
