/**
 * The water's fog as the CPU needs it: how far under the water anything can still be seen.
 * The shaders' fog is shaders/waterVolume.glsl: transmittance exp(-fogDensity · extinction · d)
 * per channel, the colour behind weighted by it and the water's own colour by the rest.
 */

/** Per-channel extinction relative to fogDensity: pure water absorbs red about 2.5 times as fast as green. */
export const WATER_EXTINCTION = [2.5, 1.0, 0.8] as const;

/** How fast daylight fades with depth, per metre, per channel (red first, as the extinction). */
export const DEPTH_DARKENING = [0.12, 0.045, 0.03] as const;

/** The share of the daylight, per channel, left at `depth` metres under the surface (1 at or above it). */
export function daylightAtDepth(depth: number): [number, number, number] {
  const d = Math.max(depth, 0);
  return [Math.exp(-DEPTH_DARKENING[0] * d), Math.exp(-DEPTH_DARKENING[1] * d), Math.exp(-DEPTH_DARKENING[2] * d)];
}

/**
 * The transmittance below which what lies behind the water no longer shows: the brightest
 * colour the underwater scene keeps (8, src/render/underwater/sceneEncoding.ts) times this is 1/8192 of
 * white, under half an output level wherever the water's own colour is above 0.3 % of white
 * (sRGB's steps are finest in the dark: one level is 3·10⁻⁴ of white at 0.3 %).
 */
export const FOG_HIDES_BELOW = 1 / 65536;

/**
 * The distance, metres, past which the weakest-absorbed channel's transmittance is below
 * FOG_HIDES_BELOW: a pixel whose line of sight ends farther away is the water's colour alone,
 * whatever it ends on. Infinite without fog.
 */
export function fogHidingDistance(fogDensity: number): number {
  const weakest = Math.min(...WATER_EXTINCTION) * fogDensity;
  return weakest > 0 ? Math.log(1 / FOG_HIDES_BELOW) / weakest : Number.POSITIVE_INFINITY;
}
