import { ShaderChunk } from 'three';
import displacement from '../../shaders/displacement.glsl?raw';

/**
 * Shared GLSL pieces are registered as three.js shader chunks, so every shader that needs
 * the displacement writes `#include <oceano_displacement>` and none keeps a copy.
 */
const chunks: Record<string, string> = {
  oceano_displacement: displacement,
};

export function registerShaderChunks(): void {
  // ShaderChunk is typed with three's own chunk names only; ours are added beside them.
  const registry = ShaderChunk as unknown as Record<string, string>;
  for (const [name, source] of Object.entries(chunks)) registry[name] = source;
}
