import { Color, type IUniform } from 'three';
import { daylightAtDepth } from '../../sim/underwater/waterFog';
import { bodyColor } from '../../sim/optics/waterColor';

/** The uniforms of shaders/waterVolume.glsl. One set is shared by every material that includes it. */
export type WaterVolumeUniforms = Record<'uWaterScatter' | 'uFogDensity' | 'uWaterAtEye', IUniform>;

/** Gain from the picked (dark) deep-water colour to the light it scatters just under the surface. */
const SCATTER_GAIN = 5.5;
/** Green lift for a picked colour: shallow sunlit water reads blue-green, not the deep colour made brighter. */
const SCATTER_LIFT = new Color(0.0, 0.05, 0.035);

/**
 * The water's own colour from its optics (src/sim/optics/waterColor.ts bodyColor, the share of
 * the light the water scatters back, per channel), brought to the screen's brightness: an
 * exposure, chosen so that the scattered light is as bright (in luminance) as the picked
 * default colour's was. The colour's ratios are the optics'; only this scale is chosen.
 */
const OPTICS_EXPOSURE = 11.2;
const OPTICS_SCATTER = new Color().fromArray(bodyColor().map((r) => r * OPTICS_EXPOSURE));

export function createWaterVolumeUniforms(): WaterVolumeUniforms {
  return {
    uWaterScatter: { value: new Color() },
    uFogDensity: { value: 0 },
    uWaterAtEye: { value: new Color() },
  };
}

/**
 * The in-scattered colour is the water's own colour from its optics, or, with
 * `waterColorPicked`, follows the user's deep-water colour as the surface does; either way
 * times the daylight: a low sun puts less light into the sea (its elevation's sine, never
 * quite zero: the sky still lights it).
 */
export function applyWaterVolume(
  u: WaterVolumeUniforms,
  waterColor: string,
  waterColorPicked: boolean,
  sunHeight: number,
  fogDensity: number,
): void {
  const daylight = 0.25 + 0.75 * Math.max(0, Math.min(1, sunHeight));
  const scatter = u.uWaterScatter.value as Color;
  if (waterColorPicked) scatter.set(waterColor).multiplyScalar(SCATTER_GAIN).add(SCATTER_LIFT);
  else scatter.copy(OPTICS_SCATTER);
  scatter.multiplyScalar(daylight);
  u.uFogDensity.value = fogDensity;
}

/** The eye's depth under the surface above it (0 above the water): the water's colour there, uWaterAtEye. */
export function setEyeDepth(u: WaterVolumeUniforms, depth: number): void {
  const [r, g, b] = daylightAtDepth(depth);
  const scatter = u.uWaterScatter.value as Color;
  (u.uWaterAtEye.value as Color).setRGB(scatter.r * r, scatter.g * g, scatter.b * b);
}
