import { groupVelocity, waveNumber } from '../waves/dispersion';

/**
 * How linear theory changes a wave train as it runs into shallower water: shoaling, refraction
 * and depth-induced breaking. Each is a small formula of its own so the coast's field, the
 * tests and the lesson cards quote one definition.
 */

/** McCowan's (1894) breaker index: a solitary wave breaks when its height reaches 0.78 of the depth. */
export const MCCOWAN_BREAKER_INDEX = 0.78;

/**
 * The shoaling coefficient Ks = √(c_g0 / c_g): with no refraction the energy flux E c_g is kept,
 * and E ∝ H², so H / H0 = √(c_g0 / c_g). `referenceDepth` is where H0 is given (∞ for deep
 * water, as in the tables). Source: Dean & Dalrymple 1991 (deanDalrymple1991) §4.10;
 * Holthuijsen 2007 (holthuijsen2007) §7.3.
 */
export function shoalingCoefficient(omega: number, depth: number, referenceDepth: number): number {
  const cg0 = groupVelocity(waveNumber(omega, referenceDepth), referenceDepth);
  const cg = groupVelocity(waveNumber(omega, depth), depth);
  return Math.sqrt(cg0 / cg);
}

/**
 * Snell's law for water waves over straight parallel contours: the wavenumber along the
 * contours, k sin θ, is the same everywhere (equivalently sin θ / c is constant). Returns θ
 * (radians from the contours' normal) at `depth` for a wave at θ0 at `referenceDepth`.
 * Source: Dean & Dalrymple 1991 §4.9; Holthuijsen 2007 §7.3.3.
 */
export function snellAngle(omega: number, theta0: number, depth: number, referenceDepth: number): number {
  const k0 = waveNumber(omega, referenceDepth);
  const k = waveNumber(omega, depth);
  return Math.asin((k0 / k) * Math.sin(theta0));
}

/**
 * The refraction coefficient Kr = √(cos θ0 / cos θ) over straight parallel contours: the crests
 * turn, the ray tube widens by cos θ / cos θ0, and the same energy flux spreads over it.
 * Source: Dean & Dalrymple 1991 §4.9; Holthuijsen 2007 §7.3.3.
 */
export function refractionCoefficient(theta0: number, theta: number): number {
  return Math.sqrt(Math.cos(theta0) / Math.cos(theta));
}

/**
 * The refraction coefficient of a ray tube of any shape: Kr = √(b0 / b), b being the distance
 * between neighbouring rays (the energy flux between them is kept). Source: Holthuijsen 2007 §7.3.3.
 */
export function rayTubeCoefficient(width0: number, width: number): number {
  return Math.sqrt(width0 / width);
}

/** The highest wave that `depth` can carry, H = γ h (McCowan 1894; Thornton & Guza 1983 use it for a saturated surf zone). */
export function breakingHeight(depth: number, breakerIndex: number = MCCOWAN_BREAKER_INDEX): number {
  return breakerIndex * Math.max(0, depth);
}

/** The depth at which a wave of height H breaks, h_b = H / γ (McCowan 1894). */
export function breakingDepth(height: number, breakerIndex: number = MCCOWAN_BREAKER_INDEX): number {
  return height / breakerIndex;
}

/**
 * How much a wave of shoaled height H breaks over `depth`: 0 below 0.9 γ h, 1 from γ h on, a
 * smoothstep between so the surf's foam has a soft seaward edge. The swell takes it at each
 * instant of its envelope H = 2|Z| (coastSwellSlope.ts): a stand-in for the fraction of broken
 * waves in a random sea (Battjes & Janssen 1978), which four components do not give.
 */
export function breakingFraction(height: number, depth: number, breakerIndex: number = MCCOWAN_BREAKER_INDEX): number {
  if (depth <= 0) return height > 0 ? 1 : 0;
  const ratio = height / breakingHeight(depth, breakerIndex);
  const t = Math.min(1, Math.max(0, (ratio - 0.9) / 0.1));
  return t * t * (3 - 2 * t);
}
