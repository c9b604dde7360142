/**
 * Where a rigid hull sits on a height field: the seed's "Quiero mover el bote", with roll.
 *
 * Sign conventions (all angles in radians; three.js's right-handed frame, y up):
 * - heading: the bow's direction seen from above, 0 along −z (where the default camera
 *   looks), growing clockwise towards +x, like the sun's azimuth. Forward is
 *   (sin h, 0, −cos h) and starboard, the boat's right, is (cos h, 0, sin h).
 * - pitch: positive raises the bow.
 * - roll: positive raises the starboard side (the boat lists to port).
 * Applied as the Euler angles of three.js's order 'YXZ': rotation.y = −heading, then
 * rotation.x = pitch about the boat's beam, then rotation.z = roll about its keel line.
 */
export type HeightAt = (x: number, z: number) => number;

export interface HullSize {
  /** Bow to stern, metres (from the model's bounding box). */
  length: number;
  /** Port to starboard, metres. */
  beam: number;
}

export interface BoatPose {
  x: number;
  y: number;
  z: number;
  heading: number;
  pitch: number;
  roll: number;
}

export function forwardOf(heading: number): [number, number] {
  return [Math.sin(heading), -Math.cos(heading)];
}

export function starboardOf(heading: number): [number, number] {
  return [Math.cos(heading), Math.sin(heading)];
}

/** The five points of the surface the hull is floated on, named as the lessons name them. */
export type HullPointName = 'centre' | 'bow' | 'stern' | 'starboard' | 'port';

/**
 * Where the hull samples the surface (x, z): its centre, the bow and stern half a length
 * away along the keel, starboard and port half a beam away across it.
 */
export function hullSamplePoints(x: number, z: number, heading: number, hull: HullSize): Record<HullPointName, [number, number]> {
  const [fx, fz] = forwardOf(heading);
  const [sx, sz] = starboardOf(heading);
  const halfLength = hull.length / 2;
  const halfBeam = hull.beam / 2;
  return {
    centre: [x, z],
    bow: [x + fx * halfLength, z + fz * halfLength],
    stern: [x - fx * halfLength, z - fz * halfLength],
    starboard: [x + sx * halfBeam, z + sz * halfBeam],
    port: [x - sx * halfBeam, z - sz * halfBeam],
  };
}

/**
 * The pose that puts the hull on the surface. As in the seed, V1 is the surface point at
 * the centre and V2 the one L/2 ahead along the hull, and the tilt comes from V = V2 − V1;
 * here V is taken from stern to bow (L/2 either side of the centre), so a boat on a crest
 * lies level rather than nose-down, and likewise across the beam for roll.
 *
 * With s_f the slope bow-wards and s_s the slope to starboard, pitch = atan(s_f) and
 * roll = atan2(s_s, √(1 + s_f²)): on a plane these make the boat's up axis exactly the
 * plane's normal and its keel line lie in the plane (unit-tested), whatever the heading.
 */
export function targetPose(heightAt: HeightAt, x: number, z: number, heading: number, hull: HullSize): BoatPose {
  const points = hullSamplePoints(x, z, heading, hull);
  const centre = heightAt(...points.centre);
  const bow = heightAt(...points.bow);
  const stern = heightAt(...points.stern);
  const starboard = heightAt(...points.starboard);
  const port = heightAt(...points.port);
  const slopeForward = (bow - stern) / hull.length;
  const slopeStarboard = (starboard - port) / hull.beam;
  return {
    x,
    y: centre,
    z,
    heading,
    pitch: Math.atan(slopeForward),
    roll: Math.atan2(slopeStarboard, Math.sqrt(1 + slopeForward * slopeForward)),
  };
}

/**
 * The boat's axes in world space for a pose, by the conventions above: forward, up and
 * starboard unit vectors (rotation matrix Ry(−heading) · Rx(pitch) · Rz(roll)).
 */
export function poseAxes(pose: Pick<BoatPose, 'heading' | 'pitch' | 'roll'>): {
  forward: [number, number, number];
  up: [number, number, number];
  starboard: [number, number, number];
} {
  const ch = Math.cos(pose.heading);
  const sh = Math.sin(pose.heading);
  const cp = Math.cos(pose.pitch);
  const sp = Math.sin(pose.pitch);
  const cr = Math.cos(pose.roll);
  const sr = Math.sin(pose.roll);
  // Ry(−h) maps local (x, y, z) to (x cos h − z sin h, y, x sin h + z cos h).
  const yaw = ([x, y, z]: [number, number, number]): [number, number, number] => [x * ch - z * sh, y, x * sh + z * ch];
  // Rx(p)·Rz(r) applied to the model's −z (bow), +y (up) and +x (starboard).
  return {
    forward: yaw([0, sp, -cp]),
    up: yaw([-sr, cr * cp, cr * sp]),
    starboard: yaw([cr, sr * cp, sr * sp]),
  };
}
