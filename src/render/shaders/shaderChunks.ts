import { ShaderChunk } from 'three';
import tiledHeightmap from '../../../shaders/tiledHeightmap.glsl?raw';
import waterVolume from '../../../shaders/waterVolume.glsl?raw';
import caustics from '../../../shaders/caustics.glsl?raw';
import waterline from '../../../shaders/waterline.glsl?raw';
import lineOfSight from '../../../shaders/lineOfSight.glsl?raw';
import wake from '../../../shaders/wake.glsl?raw';
import sinTurns from '../../../shaders/sinTurns.glsl?raw';
import skyCube from '../../../shaders/skyCube.glsl?raw';
import { shaderConstantsChunk } from './shaderConstants';
import { ENCODING_COLORSPACE_FRAGMENT, SCENE_DECODE_CHUNK } from '../underwater/sceneEncoding';

/**
 * Shared GLSL pieces are registered as three.js shader chunks, so every shader that needs
 * one writes `#include <oceano_…>` and none keeps a copy. The waves themselves are each
 * model's own chunk, registered by its view (src/render/waves/).
 */
const chunks: Record<string, string> = {
  // #defines made from the TypeScript constants the shaders share (index of refraction, …).
  oceano_constants: shaderConstantsChunk(),
  // Exact sin/cos of phases in turns: the seed's swell, the Gerstner sum and the wake share it.
  oceano_sin_turns: sinTurns,
  oceano_tiled_heightmap: tiledHeightmap,
  // The sky cube's sampler and its decoding (the default sky's cube holds square roots).
  oceano_sky_cube: skyCube,
  oceano_water_volume: waterVolume,
  // Needs <oceano_waves> included before it; see src/render/underwater/causticsUniforms.ts.
  oceano_caustics: caustics,
  // Needs <oceano_waves> included before it: the underwater passes' waterline test.
  oceano_waterline: waterline,
  // A full-screen pass's line of sight from the eye and the depth buffer (needs <packing> first).
  oceano_line_of_sight: lineOfSight,
  // The boat's Kelvin wake and its foam, added to whichever wave model is active; uniforms in src/render/wake/wakeUniforms.ts.
  oceano_wake: wake,
  // The underwater passes' reading of their scene target; see src/render/underwater/sceneEncoding.ts.
  oceano_scene_decode: SCENE_DECODE_CHUNK,
  // three.js's own chunk, ending every material, with the scene target's encoding appended.
  colorspace_fragment: ENCODING_COLORSPACE_FRAGMENT,
};

/** ShaderChunk is typed with three's own chunk names only; ours are added beside them. */
export function registerChunk(name: string, source: string): void {
  (ShaderChunk as unknown as Record<string, string>)[name] = source;
}

export function registerShaderChunks(): void {
  for (const [name, source] of Object.entries(chunks)) registerChunk(name, source);
}
