import type { Material } from 'three';

/**
 * Compiles a #define in or out of a material: a case is compiled in rather than branched on
 * (perf: on a GPU the program is smaller to compile and holds no registers for the case left
 * out; a software rasterizer, which runs both sides of a branch, also saves the untaken side:
 * docs/performance.md). Only a change marks the material for
 * recompiling, and three.js keeps each compiled variant, so switching back and forth compiles
 * each once.
 */
export function setMaterialDefine(material: Material, name: string, on: boolean): void {
  const defines = (material.defines ??= {}) as Record<string, string>;
  if (name in defines === on) return;
  if (on) defines[name] = '';
  else delete defines[name];
  material.needsUpdate = true;
}
