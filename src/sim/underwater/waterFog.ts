import { molecularScattering, PURE_WATER_ABSORPTION, WAVELENGTHS } from '../optics/waterColor';

/**
 * The water's fog as the CPU needs it: how far under the water anything can still be seen.
 * The shaders' fog is shaders/waterVolume.glsl: transmittance exp(-fogDensity · extinction · d)
 * per channel, the colour behind weighted by it and the water's own colour by the rest.
 */

type Rgb = readonly [number, number, number];
const perChannel = (value: (channel: number) => number): Rgb => [value(0), value(1), value(2)];

/** Pure water's scattering b and beam attenuation c = a + b, m⁻¹, at the screen's three wavelengths (src/sim/optics/waterColor.ts: Pope & Fry 1997, Morel 1974). */
const SCATTERING = WAVELENGTHS.map(molecularScattering);
const BEAM_ATTENUATION = PURE_WATER_ABSORPTION.map((a, i) => a + SCATTERING[i]);

/**
 * Per-channel extinction relative to fogDensity, which is the green channel's (510 nm) beam
 * attenuation: pure water's spectrum, c(λ) / c(510 nm) = 9.7 : 1 : 0.43, so red is gone within
 * a few metres and blue carries farthest. The default density, 0.035 m⁻¹, is pure water's own
 * c(510 nm); a larger one stands for water with more in it, at the same spectral shape.
 */
export const WATER_EXTINCTION = perChannel((i) => BEAM_ATTENUATION[i] / BEAM_ATTENUATION[1]);

/**
 * How fast daylight fades with depth, per metre, per channel (red first): the diffuse
 * attenuation of pure water for a sun overhead, K_d ≈ 1.0395 (a + b_b) with b_b = b / 2
 * (Gordon, H. R. 1989, "Can the Lambert-Beer law be applied to the diffuse attenuation
 * coefficient of ocean water?", Limnol. Oceanogr. 34(8), 1389–1409).
 */
export const DEPTH_DARKENING = perChannel((i) => 1.0395 * (PURE_WATER_ABSORPTION[i] + SCATTERING[i] / 2));

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
