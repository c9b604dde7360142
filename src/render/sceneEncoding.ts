import { ShaderChunk, type Material, type Object3D } from 'three';
import sceneEncode from '../../shaders/sceneEncode.glsl?raw';
import sceneDecode from '../../shaders/sceneDecode.glsl?raw';
import { glslFloat } from './shaderConstants';

/**
 * The brightest linear colour the underwater passes' scene target keeps. Seen from below, the
 * sun's glint on a spectral sea reaches 29 (waves=fft, 20 m/s); the fog then dims it, and the
 * output clips at 1. Within 4 the picture is that of a half-float target (see README,
 * Performance, tenth stop).
 */
export const SCENE_HEADROOM = 4;
const DEFINE = 'OCEANO_SCENE_HEADROOM';
const THREE_COLORSPACE_FRAGMENT = ShaderChunk.colorspace_fragment;

/**
 * three.js's colorspace_fragment with the encoding appended (shaders/sceneEncode.glsl), so
 * every material's last chunk can encode; shaderChunks.ts puts it in place of three's.
 */
export const ENCODING_COLORSPACE_FRAGMENT = `${THREE_COLORSPACE_FRAGMENT}\n${sceneEncode}`;

/** `#include <oceano_scene_decode>`: the passes that read the target (shaders/sceneDecode.glsl). */
export const SCENE_DECODE_CHUNK = `const float SCENE_HEADROOM = ${glslFloat(SCENE_HEADROOM)};\n${sceneDecode}`;

function setEncoding(material: Material, on: boolean): void {
  const defines = (material.defines ??= {}) as Record<string, string>;
  if (DEFINE in defines === on) return;
  if (on) defines[DEFINE] = glslFloat(SCENE_HEADROOM);
  else delete defines[DEFINE];
  material.needsUpdate = true;
}

/**
 * On: every material in the scene writes square roots (for the underwater passes' RGBA8
 * target); off: plain linear colour (the canvas). Flips only the materials whose state
 * differs, so calling it every frame costs a traversal; three.js keeps both compiled variants.
 */
export function encodeSceneAsSquareRoots(scene: Object3D, on: boolean): void {
  scene.traverse((object) => {
    const material = (object as Object3D & { material?: Material | Material[] }).material;
    if (!material) return;
    if (Array.isArray(material)) for (const m of material) setEncoding(m, on);
    else setEncoding(material, on);
  });
}
