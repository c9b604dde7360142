/**
 * The little geometry the chunk manager needs, without three.js so it runs and is tested
 * in node: planes whose positive side is inside (three's Frustum convention), axis-aligned
 * boxes, and the classic p-vertex / n-vertex box test.
 */
export interface Plane {
  nx: number;
  ny: number;
  nz: number;
  /** Signed distance of a point p is n·p + d; inside where it is ≥ 0. */
  d: number;
}

export const OUTSIDE = 0;
export const INSIDE = 1;
export const STRADDLES = 2;
export type BoxClass = typeof OUTSIDE | typeof INSIDE | typeof STRADDLES;

/**
 * Wholly outside when the box's corner furthest along some plane's normal is behind it;
 * wholly inside when even the nearest corner is in front of every plane. The test is
 * conservative: a box near a frustum corner may be called STRADDLES while outside, never
 * the reverse, and a box inside a bigger box never gets a "more visible" answer.
 */
export function classifyBox(
  planes: readonly Plane[],
  minX: number,
  minY: number,
  minZ: number,
  maxX: number,
  maxY: number,
  maxZ: number,
): BoxClass {
  let result: BoxClass = INSIDE;
  for (let k = 0; k < planes.length; k++) {
    const p = planes[k];
    const farX = p.nx >= 0 ? maxX : minX;
    const farY = p.ny >= 0 ? maxY : minY;
    const farZ = p.nz >= 0 ? maxZ : minZ;
    if (p.nx * farX + p.ny * farY + p.nz * farZ + p.d < 0) return OUTSIDE;
    const nearX = p.nx >= 0 ? minX : maxX;
    const nearY = p.ny >= 0 ? minY : maxY;
    const nearZ = p.nz >= 0 ? minZ : maxZ;
    if (p.nx * nearX + p.ny * nearY + p.nz * nearZ + p.d < 0) result = STRADDLES;
  }
  return result;
}

export function pointInside(planes: readonly Plane[], x: number, y: number, z: number): boolean {
  for (const p of planes) if (p.nx * x + p.ny * y + p.nz * z + p.d < 0) return false;
  return true;
}

/** Euclidean distance from a point to the nearest point of a box (0 inside it). */
export function distanceToBox(
  x: number,
  y: number,
  z: number,
  minX: number,
  minY: number,
  minZ: number,
  maxX: number,
  maxY: number,
  maxZ: number,
): number {
  const dx = x < minX ? minX - x : x > maxX ? x - maxX : 0;
  const dy = y < minY ? minY - y : y > maxY ? y - maxY : 0;
  const dz = z < minZ ? minZ - z : z > maxZ ? z - maxZ : 0;
  return Math.sqrt(dx * dx + dy * dy + dz * dz);
}

/**
 * The six planes of a perspective camera from its column-major view-projection matrix
 * (Gribb–Hartmann), normalised; the same construction three's Frustum uses, so node tests
 * can build frustums without three.
 */
export function planesFromMatrix(m: ArrayLike<number>): Plane[] {
  const row = (r: number) => [m[r], m[4 + r], m[8 + r], m[12 + r]];
  const [r0, r1, r2, r3] = [row(0), row(1), row(2), row(3)];
  const combos = [
    r3.map((v, i) => v - r0[i]),
    r3.map((v, i) => v + r0[i]),
    r3.map((v, i) => v + r1[i]),
    r3.map((v, i) => v - r1[i]),
    r3.map((v, i) => v - r2[i]),
    r3.map((v, i) => v + r2[i]),
  ];
  return combos.map(([a, b, c, d]) => {
    const length = Math.hypot(a, b, c);
    return { nx: a / length, ny: b / length, nz: c / length, d: d / length };
  });
}
