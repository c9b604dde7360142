import { Vector4, type IUniform, type Texture } from 'three';
import type { SurfaceState } from '../../../sim/waves/seed/seedSurface';

/** The uniforms of shaders/waves/seed.glsl, shared (the same objects) by every material that includes it. */
export type SurfaceUniforms = Record<
  | 'uSwellAmplitude'
  | 'uSwellFrequency'
  | 'uSwellPhase'
  | 'uRippleStrength'
  | 'uRippleBlend'
  | 'uRippleOffset'
  | 'uTileSize'
  | 'uHeightmapSize'
  | 'uNormalDelta'
  | 'uHeightmap0'
  | 'uHeightmap1'
  | 'uSlopeRoughness',
  IUniform
>;

export function createSurfaceUniforms(heightmaps?: [Texture, Texture]): SurfaceUniforms {
  const uniforms: SurfaceUniforms = {
    uSwellAmplitude: { value: 0 },
    uSwellFrequency: { value: 0 },
    uSwellPhase: { value: new Vector4() },
    uRippleStrength: { value: 0 },
    uRippleBlend: { value: 0 },
    uRippleOffset: { value: new Vector4() },
    uTileSize: { value: 1 },
    uHeightmapSize: { value: 1 },
    uNormalDelta: { value: 1 },
    uHeightmap0: { value: null },
    uHeightmap1: { value: null },
    uSlopeRoughness: { value: 0 },
  };
  if (heightmaps) applyHeightmaps(uniforms, heightmaps);
  return uniforms;
}

export function applySurfaceState(u: SurfaceUniforms, state: SurfaceState): void {
  u.uSwellAmplitude.value = state.swellAmplitude;
  u.uSwellFrequency.value = state.swellFrequency;
  (u.uSwellPhase.value as Vector4).fromArray(state.swellPhase);
  u.uRippleStrength.value = state.rippleStrength;
  u.uRippleBlend.value = state.rippleBlend;
  (u.uRippleOffset.value as Vector4).fromArray(state.rippleOffset);
  u.uTileSize.value = state.tileSize;
  u.uNormalDelta.value = state.normalDelta;
}

export function applyHeightmaps(u: SurfaceUniforms, heightmaps: [Texture, Texture]): void {
  u.uHeightmap0.value = heightmaps[0];
  u.uHeightmap1.value = heightmaps[1];
  u.uHeightmapSize.value = (heightmaps[0].image as { width: number }).width;
}
