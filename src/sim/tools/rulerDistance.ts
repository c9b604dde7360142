/**
 * The ruler's measure: the horizontal distance between two points on the sea, metres, as a
 * chart measures it. It is what a wavelength is (the distance between crests, seen from
 * above), so it can be set against the dispersion relation's 2π/k. The heights of the two
 * ends are not counted: a ruler laid from crest to trough would otherwise read more than the
 * distance the waves travel.
 */
export function horizontalDistance(a: { x: number; z: number }, b: { x: number; z: number }): number {
  return Math.hypot(b.x - a.x, b.z - a.z);
}

/** The point a fraction `f` of the way from a to b (0: a, 1: b), to sample the sea along the ruler. */
export function along(a: { x: number; z: number }, b: { x: number; z: number }, f: number): { x: number; z: number } {
  return { x: a.x + f * (b.x - a.x), z: a.z + f * (b.z - a.z) };
}
