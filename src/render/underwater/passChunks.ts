import lineOfSight from '../../../shaders/lineOfSight.glsl?raw';
import sceneDecode from '../../../shaders/sceneDecode.glsl?raw';
import { SCENE_CONSTANTS } from './sceneEncoding';

/** `#include <oceano_scene_decode>`: the passes' reading of the scene target (shaders/sceneDecode.glsl). */
export const SCENE_DECODE_CHUNK = `${SCENE_CONSTANTS}${sceneDecode}`;

/**
 * The chunks only the underwater passes include: a full-screen pass's line of sight from the
 * eye and the depth buffer (needs <packing> first), and the scene target's decoding. Their
 * text comes with the passes' code, fetched on the first dive, not with the ocean's.
 */
const PASS_CHUNKS: Readonly<Record<string, string>> = {
  oceano_line_of_sight: lineOfSight,
  oceano_scene_decode: SCENE_DECODE_CHUNK,
};

/** The source with the passes' own includes put in place; every other include is left for resolveChunks or the wave binding. */
export function withPassChunks(source: string): string {
  return source.replace(/^[ \t]*#include +<(oceano_line_of_sight|oceano_scene_decode)>/gm, (_line, name: string) => PASS_CHUNKS[name]);
}
