import { Vector2, Vector4, type IUniform } from 'three';
import { TRACK_POINTS } from '../../sim/wake/wakeTrack';
import type { WakeUniformData } from '../../sim/wake/wakeUniformData';

/**
 * The uniforms of shaders/wake.glsl (chunk `oceano_wake`): every material that includes the
 * chunk owns one set, filled each frame from packWakeUniforms (src/sim/wake/wakeUniformData.ts).
 * uWakeTrack is one flat Float32Array of TRACK_POINTS vec4s, which three uploads with
 * uniform4fv as it is.
 */
export type WakeUniforms = Record<'uWakeTrack' | 'uWakeCount' | 'uWakeOrigin' | 'uWakeParams' | 'uWakeTaper' | 'uWakeFoam', IUniform>;

export function createWakeUniforms(): WakeUniforms {
  return {
    uWakeTrack: { value: new Float32Array(TRACK_POINTS * 4) },
    uWakeCount: { value: 0 },
    uWakeOrigin: { value: new Vector2() },
    uWakeParams: { value: new Vector4() },
    uWakeTaper: { value: new Vector2(1, 2) },
    uWakeFoam: { value: new Vector4(1, 1, 1, 1) },
  };
}

export function applyWakeUniforms(u: WakeUniforms, data: WakeUniformData): void {
  (u.uWakeTrack.value as Float32Array).set(data.track);
  u.uWakeCount.value = data.count;
  (u.uWakeOrigin.value as Vector2).fromArray(data.origin);
  (u.uWakeParams.value as Vector4).fromArray(data.params);
  (u.uWakeTaper.value as Vector2).fromArray(data.taper);
  (u.uWakeFoam.value as Vector4).fromArray(data.foam);
}
