import { CustomToneMapping, ShaderChunk, type WebGLRenderer } from 'three';
import { resolveChunks } from '../shaders/shaderChunks';

/** three.js's placeholder for a custom curve, in the tone-mapping functions it puts before every fragment shader. */
const PLACEHOLDER = 'vec3 CustomToneMapping( vec3 color ) { return color; }';

/**
 * Our curve (shaders/highlightRollOff.glsl) in that placeholder's place. three.js documents this
 * as the way to give CustomToneMapping a body; only renderers set to CustomToneMapping call it.
 */
function withHighlightRollOff(chunk: string): string {
  const rollOff = resolveChunks('#include <oceano_highlight_roll_off>');
  const body = 'vec3 CustomToneMapping( vec3 color ) { return rollOffHighlights( toneMappingExposure * color ); }';
  return chunk.replace(PLACEHOLDER, `${rollOff}\n${body}`);
}

/**
 * Draws every pixel of `renderer`'s frames through the highlight roll-off
 * (src/sim/optics/highlightRollOff.ts): the sea, the sky with its sun, the boat, and the
 * underwater passes' last step alike, as a camera's one curve does. three.js then runs it at
 * the end of every shader that draws to the canvas (its `tonemapping_fragment`); a pass into a
 * render target keeps linear light for the pass after it.
 *
 * Returns false, leaving the renderer as it was, where this three.js has no such placeholder:
 * the sea then rolls its own highlights off (OceanMaterial) and the rest clips at white.
 */
export function drawThroughHighlightRollOff(renderer: WebGLRenderer): boolean {
  if (!ShaderChunk.tonemapping_pars_fragment.includes('rollOffHighlights')) {
    if (!ShaderChunk.tonemapping_pars_fragment.includes(PLACEHOLDER)) return false;
    ShaderChunk.tonemapping_pars_fragment = withHighlightRollOff(ShaderChunk.tonemapping_pars_fragment);
  }
  renderer.toneMapping = CustomToneMapping;
  return true;
}

/** Whether `renderer` draws through our curve (drawThroughHighlightRollOff), so a shader may use the curve's inverse. */
export function runsHighlightRollOff(renderer: WebGLRenderer): boolean {
  return renderer.toneMapping === CustomToneMapping && ShaderChunk.tonemapping_pars_fragment.includes('rollOffHighlights');
}
