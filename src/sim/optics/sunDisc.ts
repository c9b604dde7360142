/**
 * The sun's disc (angular radius 0.2666°, 4.65 mrad) as a slope variance: a uniform disc of
 * radius r has r²/4 of variance per axis; the half vector moves by half the angle, so the
 * facets that catch some of the disc spread by (r/2)²/4 per axis, r²/8 in all. The floor of
 * the roughness: a mirror still reflects a sun of finite size.
 */
export const SUN_DISC_SLOPE_VARIANCE = 0.00465 ** 2 / 8;

/**
 * The disc as the sky draws it: a coverage that rises from 0 to 1 (smoothstep) as the cosine
 * of the angle from the sun's centre goes from SUN_DISC_COS_EDGE to SUN_DISC_COS_CORE, that is
 * between 0.99° and 0.72° from it. That is larger than the real disc (0.27°), so that it spans
 * some 20 pixels of a 720-pixel-high view rather than 7; the glint on the sea keeps the real
 * size (SUN_DISC_SLOPE_VARIANCE).
 */
export const SUN_DISC_COS_EDGE = 0.99985;
export const SUN_DISC_COS_CORE = 0.99992;
/** The middle of that edge: the sharp disc of the same solid angle, which the sky behind the scene draws in full brightness. */
export const SUN_DISC_COS_MID = (SUN_DISC_COS_EDGE + SUN_DISC_COS_CORE) / 2;

/**
 * The drawn disc's solid angle, in steradians: 2π ∫ coverage d(cos θ), the full disc inside the
 * core plus half the smoothstep's ramp (a smoothstep averages ½ over its ramp), which is the
 * sharp disc out to the ramp's middle: 2π (1 − SUN_DISC_COS_MID), 7.2·10⁻⁴ sr.
 */
export const SUN_DISC_SOLID_ANGLE = 2 * Math.PI * (1 - SUN_DISC_COS_MID);

/**
 * The drawn disc's radiance, in the sky's units: the sun's irradiance (SUN_IRRADIANCE, what the
 * glint reflects) spread over the disc's solid angle, about 5,500 times the sky's white. What
 * a display shows of it is the tone curve's white (src/sim/optics/highlightRollOff.ts), where the
 * cube's disc, white (1), shows as the curve's 0.85.
 */
export function sunDiscRadiance(irradiance: number): number {
  return irradiance / SUN_DISC_SOLID_ANGLE;
}
