import { Color, type IUniform } from 'three';
import { daylightAtDepth } from '../../sim/underwater/waterFog';

/** The uniforms of shaders/waterVolume.glsl. One set is shared by every material that includes it. */
export type WaterVolumeUniforms = Record<'uWaterScatter' | 'uFogDensity' | 'uWaterAtEye', IUniform>;

/** Gain from the (dark) deep-water colour to the light it scatters just under the surface. */
const SCATTER_GAIN = 5.5;
/** Green lift: shallow sunlit water reads blue-green, not the deep colour made brighter. */
const SCATTER_LIFT = new Color(0.0, 0.05, 0.035);

export function createWaterVolumeUniforms(): WaterVolumeUniforms {
  return {
    uWaterScatter: { value: new Color() },
    uFogDensity: { value: 0 },
    uWaterAtEye: { value: new Color() },
  };
}

/**
 * The in-scattered colour follows the user's deep-water colour and the daylight: a low sun
 * puts less light into the sea (its elevation's sine, never quite zero: the sky still lights it).
 */
export function applyWaterVolume(u: WaterVolumeUniforms, waterColor: string, sunHeight: number, fogDensity: number): void {
  const daylight = 0.25 + 0.75 * Math.max(0, Math.min(1, sunHeight));
  (u.uWaterScatter.value as Color).set(waterColor).multiplyScalar(SCATTER_GAIN).add(SCATTER_LIFT).multiplyScalar(daylight);
  u.uFogDensity.value = fogDensity;
}

/** The eye's depth under the surface above it (0 above the water): the water's colour there, uWaterAtEye. */
export function setEyeDepth(u: WaterVolumeUniforms, depth: number): void {
  const [r, g, b] = daylightAtDepth(depth);
  const scatter = u.uWaterScatter.value as Color;
  (u.uWaterAtEye.value as Color).setRGB(scatter.r * r, scatter.g * g, scatter.b * b);
}
