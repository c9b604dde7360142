/**
 * Where a ray from the eye meets the sea: the point a click picks. The sea is a height field
 * y = h(x, z) that lies within ±maxHeight of the mean level y = 0, so the first crossing lies
 * where the ray passes through that slab. The ray is walked through the slab in short steps
 * until the sign of (ray height − sea height) changes, then the crossing is refined by
 * bisection. Stepping, not Newton from the mean plane: a grazing ray can pass over one crest
 * and meet the next, and only the first crossing is what the eye sees.
 */

export type Vec3 = readonly [number, number, number];

/** Height of the sea above the world point (x, z), metres. */
export type SeaHeight = (x: number, z: number) => number;

export interface SeaPickOptions {
  /** The largest |height| of the sea, metres (the wave model's bounds): the slab to search. */
  maxHeight: number;
  /** Farther than this along the ray, metres, counts as a miss (the horizon). */
  maxDistance?: number;
  /** Largest step along the ray, metres: well under half the shortest wave, so no crest is stepped over. */
  step?: number;
}

export interface SeaPoint {
  x: number;
  y: number;
  z: number;
  /** Distance from the ray's origin, metres. */
  distance: number;
}

const DEFAULT_MAX_DISTANCE = 2000;
const DEFAULT_STEP = 0.25;
/** Bisection halvings: 0.25 m / 2⁴⁰ is far below a millimetre. */
const BISECTIONS = 40;

/** Where the ray meets the plane y = level, or null when it runs parallel or away from it. */
export function rayPlane(origin: Vec3, direction: Vec3, level = 0): SeaPoint | null {
  const dy = direction[1];
  if (dy === 0) return null;
  const s = (level - origin[1]) / dy;
  if (!(s >= 0)) return null;
  const length = Math.hypot(direction[0], direction[1], direction[2]);
  return { x: origin[0] + s * direction[0], y: level, z: origin[2] + s * direction[2], distance: s * length };
}

/**
 * The first point where the ray origin + s·direction (s ≥ 0) meets the sea, or null when it
 * misses within maxDistance (a ray into the sky). The ray may start above or below the water.
 */
export function pickSea(origin: Vec3, direction: Vec3, height: SeaHeight, options: SeaPickOptions): SeaPoint | null {
  const length = Math.hypot(direction[0], direction[1], direction[2]);
  if (!(length > 0) || !(options.maxHeight >= 0)) return null;
  const d = [direction[0] / length, direction[1] / length, direction[2] / length] as const;
  const maxDistance = options.maxDistance ?? DEFAULT_MAX_DISTANCE;
  const step = options.step ?? DEFAULT_STEP;
  // The part of the ray inside the slab |y| ≤ maxHeight: [enter, leave] in metres along it.
  const slab = options.maxHeight;
  let enter = 0;
  let leave = maxDistance;
  if (d[1] === 0) {
    if (Math.abs(origin[1]) > slab) return null;
  } else {
    const a = (slab - origin[1]) / d[1];
    const b = (-slab - origin[1]) / d[1];
    enter = Math.max(0, Math.min(a, b));
    leave = Math.min(maxDistance, Math.max(a, b));
  }
  if (enter > leave) return null;
  const gap = (s: number) => origin[1] + s * d[1] - height(origin[0] + s * d[0], origin[2] + s * d[2]);
  let s0 = enter;
  let g0 = gap(s0);
  if (g0 === 0) return point(origin, d, s0, height);
  while (s0 < leave) {
    const s1 = Math.min(s0 + step, leave);
    const g1 = gap(s1);
    if (g1 === 0 || g1 < 0 !== g0 < 0) return point(origin, d, bisect(gap, s0, s1, g0), height);
    s0 = s1;
    g0 = g1;
  }
  return null;
}

/** The root of `gap` between a and b (where it changes sign), by halving. */
function bisect(gap: (s: number) => number, a: number, b: number, ga: number): number {
  let lo = a;
  let hi = b;
  for (let i = 0; i < BISECTIONS; i++) {
    const mid = 0.5 * (lo + hi);
    const g = gap(mid);
    if (g === 0) return mid;
    if (g < 0 === ga < 0) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

function point(origin: Vec3, d: Vec3, s: number, height: SeaHeight): SeaPoint {
  const x = origin[0] + s * d[0];
  const z = origin[2] + s * d[2];
  return { x, y: height(x, z), z, distance: s };
}
