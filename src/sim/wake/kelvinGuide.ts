import { forwardOf } from '../boat/boatPose';

/** Kelvin's half-angle, arcsin(1/3) ≈ 19.47° (Kelvin 1887; Lighthill, Waves in Fluids, §3.10). */
export const KELVIN_HALF_ANGLE = Math.asin(1 / 3);

/**
 * The teaching overlay's two lines (`wakeGuide`): from the boat's centre, where the wake's
 * sources start, backwards at ±19.47° from its stern direction, `length` metres long.
 * Returns [apexX, apexZ, portEndX, portEndZ, starboardEndX, starboardEndZ]. It is drawn from
 * theory on purpose, so the wake the physics makes can be compared with it.
 */
export function kelvinGuideLines(x: number, z: number, heading: number, length: number): [number, number, number, number, number, number] {
  const [fx, fz] = forwardOf(heading);
  const c = Math.cos(KELVIN_HALF_ANGLE) * length;
  const s = Math.sin(KELVIN_HALF_ANGLE) * length;
  // Backwards is −forward; the perpendicular (−fz, fx) points to port for the y-up frame of boatPose.ts.
  return [x, z, x - fx * c - fz * s, z - fz * c + fx * s, x - fx * c + fz * s, z - fz * c - fx * s];
}
