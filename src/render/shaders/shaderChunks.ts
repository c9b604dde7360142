import tiledHeightmap from '../../../shaders/tiledHeightmap.glsl?raw';
import waterVolume from '../../../shaders/waterVolume.glsl?raw';
import caustics from '../../../shaders/caustics.glsl?raw';
import waterline from '../../../shaders/waterline.glsl?raw';
import sinTurns from '../../../shaders/sinTurns.glsl?raw';
import skyCube from '../../../shaders/skyCube.glsl?raw';
import subsurface from '../../../shaders/subsurface.glsl?raw';
import haze from '../../../shaders/haze.glsl?raw';
import fresnelLookup from '../../../shaders/fresnelLookup.glsl?raw';
import waterBody from '../../../shaders/waterBody.glsl?raw';
import highlightRollOff from '../../../shaders/highlightRollOff.glsl?raw';
import sunDisc from '../../../shaders/sunDisc.glsl?raw';
import { shaderConstantsChunk } from './shaderConstants';
import { SCENE_ENCODE_CHUNK } from '../underwater/sceneEncoding';

/**
 * Oceano's shared GLSL pieces. A shader that needs one writes `#include <oceano_…>`, and
 * resolveChunks puts the text in place before the material is made, so none keeps a copy
 * and three.js's own ShaderChunk table is left as three ships it. three's own includes
 * (`<common>`, `<colorspace_fragment>` …) stay for three to resolve.
 */
const CHUNKS: Readonly<Record<string, string>> = {
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
  // Thin sunlit crests glowing (ocean.frag, OCEAN_SUBSURFACE).
  oceano_subsurface: subsurface,
  // The air's haze between the eye and the sea (ocean.vert's near bands, ocean.frag's far ones).
  oceano_haze: haze,
  // The exact Fresnel reflectance from its table (the ocean's pixels, and its vertices for the water's colour).
  oceano_fresnel_lookup: fresnelLookup,
  // The water's own colour from its optics, the same everywhere: worked out per vertex (ocean.vert).
  oceano_water_body: waterBody,
  // The whole frame's tone curve: the app's renderer runs it on every pixel (src/render/tone/wholeFrameToneCurve.ts).
  oceano_highlight_roll_off: highlightRollOff,
  // The sun's disc in the sky: where it is (the painted cube, the sky behind the scene) and how bright.
  oceano_sun_disc: sunDisc,
  // The underwater passes' scene target, written after three's colour-space chunk (read back by
  // the passes' own chunks, src/render/underwater/passChunks.ts).
  oceano_scene_encode: SCENE_ENCODE_CHUNK,
};

const INCLUDE = /^[ \t]*#include +<(oceano_[a-z_]+)>/gm;

/**
 * The source with every `#include <oceano_…>` replaced by its text, recursively: `extra`'s
 * chunks first (a model's waves, a pass's own pieces), then the shared ones above. An unknown
 * name throws, naming it.
 */
export function resolveChunks(source: string, extra: Readonly<Record<string, string>> = {}): string {
  return source.replace(INCLUDE, (_line, name: string) => {
    const text = extra[name] ?? CHUNKS[name];
    if (text === undefined) throw new Error(`Unknown shader chunk <${name}>.`);
    return resolveChunks(text, extra);
  });
}
