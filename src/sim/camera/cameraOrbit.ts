/**
 * Orbiting the eye about its target by angles and a distance factor, in spherical
 * coordinates about +y (the OrbitControls convention): what the camera keys do.
 */
export type Vec3 = [number, number, number];

/** Closest the polar angle comes to the poles, radians: keeps the view direction defined. */
const POLE_MARGIN = 0.01;

/**
 * @param yaw radians added to the azimuth about +y (positive: the eye moves counter-clockwise seen from above)
 * @param pitch radians added to the polar angle from +y (positive: the eye moves down)
 * @param zoom factor on the eye's distance to the target
 */
export function orbit(position: Vec3, target: Vec3, yaw: number, pitch: number, zoom: number, minDistance = 0.5, maxDistance = 1e5): Vec3 {
  const dx = position[0] - target[0];
  const dy = position[1] - target[1];
  const dz = position[2] - target[2];
  const radius = Math.hypot(dx, dy, dz);
  const polar = Math.min(Math.PI - POLE_MARGIN, Math.max(POLE_MARGIN, Math.acos(Math.max(-1, Math.min(1, dy / radius))) + pitch));
  const azimuth = Math.atan2(dx, dz) + yaw;
  const r = Math.min(maxDistance, Math.max(minDistance, radius * zoom));
  return [
    target[0] + r * Math.sin(polar) * Math.sin(azimuth),
    target[1] + r * Math.cos(polar),
    target[2] + r * Math.sin(polar) * Math.cos(azimuth),
  ];
}
