import { ShaderChunk, type Material, type Object3D } from 'three';
import sceneEncode from '../../../shaders/sceneEncode.glsl?raw';
import sceneDecode from '../../../shaders/sceneDecode.glsl?raw';
import { glslFloat } from '../shaders/shaderConstants';
import { setMaterialDefine } from '../shaders/materialDefines';

/**
 * The scene target's codes for colours up to 1 (their square roots), out of 255: the other 16
 * hold a logarithmic shoulder up to SCENE_BRIGHTEST. Seen from below, the sun's glint on a
 * spectral sea reaches 29 (waves=fft, 20 m/s); the fog then dims it and the output clips at 1,
 * so the shoulder keeps it white. A square root over [0, 4] instead (every code) had steps of
 * 2 levels in the sky seen across a waterline; over [0, 1] it dimmed the sun seen from below
 * to pale blue (README, Performance, tenth stop).
 */
export const SCENE_LOW_CODES = 239;
export const SCENE_BRIGHTEST = 8;
/** Defined on a material, its colorspace_fragment writes the encoding (the god-ray pass's material is built with it). */
export const SCENE_ENCODE_DEFINE = 'OCEANO_SCENE_ENCODE';
/** Macros, not constants: the encoding runs inside main(), after whatever the shader declared. */
const CONSTANTS = [
  '#ifndef SCENE_LOW_SHARE',
  `#define SCENE_LOW_SHARE ${glslFloat(SCENE_LOW_CODES / 255)}`,
  `#define SCENE_BRIGHTEST ${glslFloat(SCENE_BRIGHTEST)}`,
  '#endif',
  '',
].join('\n');
const THREE_COLORSPACE_FRAGMENT = ShaderChunk.colorspace_fragment;

/**
 * three.js's colorspace_fragment with the encoding appended (shaders/sceneEncode.glsl), so
 * every material's last chunk can encode; shaderChunks.ts puts it in place of three's.
 */
export const ENCODING_COLORSPACE_FRAGMENT = `${THREE_COLORSPACE_FRAGMENT}\n${CONSTANTS}${sceneEncode}`;

/** `#include <oceano_scene_decode>`: the passes that read the target (shaders/sceneDecode.glsl). */
export const SCENE_DECODE_CHUNK = `${CONSTANTS}${sceneDecode}`;

/**
 * On: every material in the scene writes the encoding (for the underwater passes' RGBA8
 * target); off: plain linear colour (the canvas). Flips only the materials whose state
 * differs, so calling it every frame costs a traversal; three.js keeps both compiled variants.
 */
export function encodeSceneForPost(scene: Object3D, on: boolean): void {
  scene.traverse((object) => {
    const material = (object as Object3D & { material?: Material | Material[] }).material;
    if (!material) return;
    for (const m of Array.isArray(material) ? material : [material]) setMaterialDefine(m, SCENE_ENCODE_DEFINE, on);
  });
}
