import { forwardOf, type HeightAt } from '../boat/boatPose';
import { VOLUME_PER_LENGTH_CUBED } from '../wake/kelvinWake';

/**
 * The boat as the interactive waves see it during one step: its waterline footprint, a solid
 * the waves reflect from, and the water its motion pushes aside at the bow and lets back in at
 * the stern. The same hull as the analytic Kelvin wake's (src/sim/wake/kelvinWake.ts), so the
 * near field (here) and the far field (there) come from one boat.
 */
export interface MovingHull {
  /** Centre of the waterline, world metres. */
  x: number;
  z: number;
  /** Radians, the convention of src/sim/boat/boatPose.ts (clockwise from −z). */
  heading: number;
  /** m/s along the heading; negative goes astern. */
  speed: number;
  /** Waterline length and beam, metres. */
  length: number;
  beam: number;
  /** Multiplies the sources (the wakeStrength parameter); 0 leaves only the obstacle. */
  strength: number;
}

/** A source of the hull: a Gaussian bump (bumpProfile) of this radius, added at rest each step. */
export interface HullSource {
  x: number;
  z: number;
  /** Metres: half the beam, so the bump is as wide as the water the hull pushes aside. */
  radius: number;
  /** Metres per second at the bump's centre; times the step, what one step adds there. */
  rate: number;
}

/**
 * Whether the world point (x, z) lies inside the hull's waterline, taken as an ellipse of the
 * hull's length and beam: a solid texel of the obstacle mask. The GLSL twin is hullMask in
 * shaders/iwaveStep.frag.
 */
export function hullCovers(hull: MovingHull, x: number, z: number): boolean {
  const [fx, fz] = forwardOf(hull.heading);
  const dx = x - hull.x;
  const dz = z - hull.z;
  const along = (dx * fx + dz * fz) / (0.5 * hull.length);
  const across = (-dx * fz + dz * fx) / (0.5 * hull.beam);
  return along * along + across * across <= 1;
}

/**
 * The near field's two sources: a hull of volume V and length L moving at U sweeps U·V/L
 * cubic metres a second (its mean cross-section times its speed). The bow pushes that much
 * water aside, a bump just ahead of it; the stern leaves as much room behind, a dip just
 * astern. Volume is kept (the two cancel), and going astern swaps them. A bump of radius a
 * holds π a²/2 times its centre height (bumpProfile), hence the rate. V = 0.0125 L³ as in
 * the analytic wake (kelvinWake.ts), so the two wakes are made by the same boat.
 */
export function hullSources(hull: MovingHull): [bow: HullSource, stern: HullSource] {
  const [fx, fz] = forwardOf(hull.heading);
  const radius = 0.5 * hull.beam;
  const reach = 0.5 * hull.length + radius;
  const flux = hull.strength * hull.speed * VOLUME_PER_LENGTH_CUBED * hull.length * hull.length;
  const rate = flux / ((Math.PI * radius * radius) / 2);
  return [
    { x: hull.x + fx * reach, z: hull.z + fz * reach, radius, rate },
    { x: hull.x - fx * reach, z: hull.z - fz * reach, radius, rate: -rate },
  ];
}

/**
 * The hull `age` seconds before `hull`, had it sailed with its present speed and turn rate
 * (radians per second) all along: what the steps between two frames, or a catch-up after a
 * jump, use for where the boat was. Exact on a straight course and on a steady turn.
 */
export function hullEarlier(hull: MovingHull, turnRate: number, age: number): MovingHull {
  if (age === 0) return hull;
  let x = hull.x;
  let z = hull.z;
  if (Math.abs(turnRate) < 1e-9) {
    const [fx, fz] = forwardOf(hull.heading);
    x -= fx * hull.speed * age;
    z -= fz * hull.speed * age;
  } else {
    // On a circle: the chord between the headings then and now, of radius U/ω.
    const before = hull.heading - turnRate * age;
    const radius = hull.speed / turnRate;
    x -= radius * (Math.cos(before) - Math.cos(hull.heading));
    z -= radius * (Math.sin(before) - Math.sin(hull.heading));
  }
  return { ...hull, x, z, heading: hull.heading - turnRate * age };
}

/**
 * `height` read from the water just outside the hull: a point inside the waterline (grown by
 * `margin` metres) is carried out along the ray from the hull's centre to that grown outline,
 * and the centre itself reads the mean of the four points ahead, astern and abeam. The
 * interactive field is held at 0 under the hull (it is a solid there), so the boat feels the
 * water around it: a wave meeting the hull lifts it, and its own bow wave trims it.
 */
export function besideHull(height: HeightAt, hull: Pick<MovingHull, 'x' | 'z' | 'heading' | 'length' | 'beam'>, margin: number): HeightAt {
  const [fx, fz] = forwardOf(hull.heading);
  const a = 0.5 * hull.length + margin;
  const b = 0.5 * hull.beam + margin;
  return (x, z) => {
    const dx = x - hull.x;
    const dz = z - hull.z;
    const along = dx * fx + dz * fz;
    const across = -dx * fz + dz * fx;
    const q = (along / a) ** 2 + (across / b) ** 2;
    if (q >= 1) return height(x, z);
    const at = (u: number, v: number) => height(hull.x + u * fx - v * fz, hull.z + u * fz + v * fx);
    if (q < 1e-12) return 0.25 * (at(a, 0) + at(-a, 0) + at(0, b) + at(0, -b));
    const out = 1 / Math.sqrt(q);
    return at(along * out, across * out);
  };
}
