import type { Material, Object3D } from 'three';
import sceneEncode from '../../../shaders/sceneEncode.glsl?raw';
import { glslFloat } from '../shaders/shaderConstants';
import { setMaterialDefine } from '../shaders/materialDefines';

/**
 * The scene target's codes for colours up to 1 (their square roots), out of 255: the other 16
 * hold a logarithmic shoulder up to SCENE_BRIGHTEST. Seen from below, the sun's glint on a
 * spectral sea reaches 29 (waves=fft, 20 m/s); the fog then dims it and the output clips at 1,
 * so the shoulder keeps it white. A square root over [0, 4] instead (every code) had steps of
 * 2 levels in the sky seen across a waterline; over [0, 1] it dimmed the sun seen from below
 * to pale blue (docs/performance.md).
 */
export const SCENE_LOW_CODES = 239;
export const SCENE_BRIGHTEST = 8;
/** Defined on a material, its colorspace_fragment writes the encoding (the god-ray pass's material is built with it). */
export const SCENE_ENCODE_DEFINE = 'OCEANO_SCENE_ENCODE';
/** Defined on the passes that read a half-float scene target, whose colours are stored as they are. */
export const SCENE_LINEAR_DEFINE = 'OCEANO_SCENE_LINEAR';
/** Marks a material built by Oceano, whose shaders end with the encoding's chunk. */
const OCEANO_MATERIAL = 'oceanoMaterial';
/** Materials of others already patched to write the encoding. */
const patched = new WeakSet<Material>();
/** Macros, not constants: the encoding runs inside main(), after whatever the shader declared. */
export const SCENE_CONSTANTS = [
  '#ifndef SCENE_LOW_SHARE',
  `#define SCENE_LOW_SHARE ${glslFloat(SCENE_LOW_CODES / 255)}`,
  `#define SCENE_BRIGHTEST ${glslFloat(SCENE_BRIGHTEST)}`,
  '#endif',
  '',
].join('\n');
/**
 * `#include <oceano_scene_encode>`, written right after three's `#include <colorspace_fragment>`
 * at the end of each of Oceano's own shaders (shaders/sceneEncode.glsl): compiled in where
 * SCENE_ENCODE_DEFINE is defined on the material.
 */
export const SCENE_ENCODE_CHUNK = `${SCENE_CONSTANTS}${sceneEncode}`;

/** Marks a material as Oceano's own: its shaders end with `#include <oceano_scene_encode>`. */
export function markOceanoMaterial<M extends Material>(material: M): M {
  material.userData[OCEANO_MATERIAL] = true;
  return material;
}

/**
 * Appends the encoding to a material of someone else's, after three's colour-space chunk,
 * chaining whatever onBeforeCompile and program key it had; once per material.
 */
function patchToEncode(material: Material): void {
  if (patched.has(material)) return;
  patched.add(material);
  const before = material.onBeforeCompile;
  const key = material.customProgramCacheKey;
  material.onBeforeCompile = (shader, renderer) => {
    before.call(material, shader, renderer);
    shader.fragmentShader = shader.fragmentShader.replace(
      '#include <colorspace_fragment>',
      `#include <colorspace_fragment>\n${SCENE_ENCODE_CHUNK}`,
    );
  };
  material.customProgramCacheKey = () => `${key.call(material)}|oceano-scene-encode`;
}

/**
 * On: the materials in the scene write the encoding (for the underwater passes' RGBA8
 * target); off: plain linear colour (the canvas). Only Oceano's own materials unless
 * `everyMaterial`, which patches the others to write it too. Flips only the materials whose
 * state differs, so calling it every frame costs a traversal; three.js keeps both compiled variants.
 */
export function encodeSceneForPost(scene: Object3D, on: boolean, everyMaterial = false): void {
  scene.traverse((object) => {
    const material = (object as Object3D & { material?: Material | Material[] }).material;
    if (!material) return;
    for (const m of Array.isArray(material) ? material : [material]) {
      const ours = m.userData[OCEANO_MATERIAL] === true;
      const encodes = on && (ours || everyMaterial);
      if (encodes && !ours) patchToEncode(m);
      if (ours || patched.has(m)) setMaterialDefine(m, SCENE_ENCODE_DEFINE, encodes);
    }
  });
}
