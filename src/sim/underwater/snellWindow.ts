import { AIR_IOR, criticalAngle, fresnelTable, WATER_IOR } from '../optics/fresnel';

/**
 * The optics of looking up from under the surface. Everything above the water is squeezed
 * into a cone around the normal, Snell's window, whose half-angle is the critical angle;
 * rays from below that meet the surface more obliquely are totally reflected.
 */
export function snellWindowHalfAngle(nWater = WATER_IOR, nAir = AIR_IOR): number {
  return criticalAngle(nWater, nAir);
}

/**
 * The reflectance seen from below, tabulated like the one from above (entry i at
 * cos θ = i / (size − 1)) but with light going from water (n₁ = 1.333) to air: every
 * entry with cos θ below cos θc is total internal reflection, exactly 1.
 */
export function fresnelTableFromBelow(size = 256): Float32Array {
  return fresnelTable(size, WATER_IOR, AIR_IOR);
}

export type Vec3 = [number, number, number];

/**
 * Snell's law in vector form, the same convention as GLSL's refract(I, N, eta): I is the
 * unit direction of travel, N the unit normal facing against it, eta = n₁ / n₂. Returns
 * null on total internal reflection.
 */
export function refractDirection(incident: Vec3, normal: Vec3, eta: number): Vec3 | null {
  const cosI = -(incident[0] * normal[0] + incident[1] * normal[1] + incident[2] * normal[2]);
  const k = 1 - eta * eta * (1 - cosI * cosI);
  if (k < 0) return null;
  const a = eta * cosI - Math.sqrt(k);
  return [eta * incident[0] + a * normal[0], eta * incident[1] + a * normal[1], eta * incident[2] + a * normal[2]];
}

/**
 * Direction in which sunlight travels under a flat sea, given the unit direction towards
 * the sun. A sun below the horizon sends no direct light into the water: null.
 */
export function refractedSunDirection(towardsSun: Vec3): Vec3 | null {
  if (towardsSun[1] <= 0) return null;
  return refractDirection([-towardsSun[0], -towardsSun[1], -towardsSun[2]], [0, 1, 0], AIR_IOR / WATER_IOR);
}

/**
 * Where the camera's view begins relative to the water. 'straddling' means the near
 * plane may cross the displaced surface, so the frame needs a per-pixel decision.
 */
export type Submersion = 'above' | 'below' | 'straddling';

/**
 * Classifies the near plane from points on it and the surface height under each point.
 * Every point clear of the surface by more than `margin` on the same side decides the
 * whole plane; anything else is treated as straddling, which is always safe to render.
 */
export function classifyNearPlane(points: readonly { y: number; surface: number }[], margin: number): Submersion {
  if (points.length === 0) throw new RangeError('classifyNearPlane needs at least one point.');
  if (points.every((p) => p.y > p.surface + margin)) return 'above';
  if (points.every((p) => p.y < p.surface - margin)) return 'below';
  return 'straddling';
}
