import { ShaderChunk } from 'three';
import displacement from '../../shaders/displacement.glsl?raw';
import waterVolume from '../../shaders/waterVolume.glsl?raw';
import caustics from '../../shaders/caustics.glsl?raw';

/**
 * Shared GLSL pieces are registered as three.js shader chunks, so every shader that needs
 * the displacement writes `#include <oceano_displacement>` and none keeps a copy.
 */
const chunks: Record<string, string> = {
  oceano_displacement: displacement,
  oceano_water_volume: waterVolume,
  // Needs oceano_displacement included before it; see src/render/causticsUniforms.ts.
  oceano_caustics: caustics,
};

export function registerShaderChunks(): void {
  // ShaderChunk is typed with three's own chunk names only; ours are added beside them.
  const registry = ShaderChunk as unknown as Record<string, string>;
  for (const [name, source] of Object.entries(chunks)) registry[name] = source;
}
