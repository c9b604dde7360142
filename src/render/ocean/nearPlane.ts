/**
 * The camera's near distance from the eye's clearance above the water. A fixed 0.5 m near
 * plane clips the surface within half a metre of the eye, so an eye 5 cm up saw the lower
 * frame from inside the water. The near plane is brought in until it lies
 * above the surface with the waterline test's margin, whatever way the camera looks:
 *
 *   a near-plane point at distance n is eye + n (F + sy·t·U + sx·t·a·R), |sx|, |sy| ≤ 1, so
 *   it lies at most n·D below the eye, D = −F_y + t (|U_y| + a |R_y|), and at most n·ρ
 *   away horizontally, ρ = √(1 + t²(1 + a²)) (t = tan(fov/2), a the aspect). The surface
 *   there rises at most SLOPE·n·ρ over its height under the eye, and the sampled test wants
 *   a margin m·n. So n (D⁺ + SLOPE·ρ + m) ≤ clearance.
 *
 * A smaller near plane costs depth precision (a 24-bit buffer resolves z²·2⁻²⁴/n), so it
 * is used only as far as needed: never above the default 0.5 m, never below NEAR_FLOOR.
 */

/** The default near plane, metres, kept whenever the eye is clear enough. */
export const DEFAULT_NEAR = 0.5;
/** The smallest near plane, metres: with 24 depth bits 1 cm resolves 6 cm at 100 m, 6 m at 1 km. */
export const NEAR_FLOOR = 0.01;
/** The steepest surface slope assumed under the near plane (27°); steeper, the sampled test says 'straddling'. */
export const SURFACE_SLOPE = 0.5;
/** The sampled test's margin per metre of near distance (0.25 m at 0.5 m, the samples' spacing). */
export const MARGIN_PER_NEAR = 0.5;

export interface ViewAxes {
  /** y components of the camera's forward, up and right unit vectors. */
  forwardY: number;
  upY: number;
  rightY: number;
  /** tan(vertical fov / 2) and the aspect ratio. */
  tanHalfFov: number;
  aspect: number;
}

/** How far below the eye the near plane reaches, per metre of near distance (negative: all above the eye). */
export function nearPlaneDrop(axes: ViewAxes): number {
  return -axes.forwardY + axes.tanHalfFov * (Math.abs(axes.upY) + axes.aspect * Math.abs(axes.rightY));
}

/** The near distance for an eye `clearance` metres above the surface under it (negative: below it). */
export function nearForClearance(clearance: number, axes: ViewAxes): number {
  if (!(clearance > 0)) return DEFAULT_NEAR;
  const reach = Math.sqrt(1 + axes.tanHalfFov ** 2 * (1 + axes.aspect ** 2));
  const perMetre = Math.max(nearPlaneDrop(axes), 0) + SURFACE_SLOPE * reach + MARGIN_PER_NEAR;
  return Math.min(DEFAULT_NEAR, Math.max(NEAR_FLOOR, clearance / perMetre));
}
