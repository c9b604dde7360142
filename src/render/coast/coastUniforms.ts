import { Vector2, Vector4, type IUniform } from 'three';

/**
 * The uniforms of shaders/coast.glsl (chunk `oceano_coast`), in every material that includes it
 * (the ocean's, the sea bed's, the GPU probe's). They are made with the ocean, empty: the coast's
 * code, fetched when `bathymetry` is not `deep`, fills them (src/render/coast/coastScene.ts).
 */
export type CoastUniforms = Record<'uCoastField' | 'uCoastGrid' | 'uCoastAdvance' | 'uCoastWind' | 'uCoastFloor', IUniform>;

export function createCoastUniforms(): CoastUniforms {
  return {
    uCoastField: { value: null },
    uCoastGrid: { value: new Vector4(0, 0, 1, 2) },
    uCoastAdvance: { value: new Vector4(0, 0, 0, 0) },
    uCoastWind: { value: new Vector2(1, 0) },
    uCoastFloor: { value: new Vector2(1, 0.02) },
  };
}
