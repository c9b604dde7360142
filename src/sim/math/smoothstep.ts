/**
 * GLSL's smoothstep, for the CPU twins of shaders that use it: 0 at edge0, 1 at edge1, the
 * cubic 3t² − 2t³ between (edge0 may be above edge1: the step then falls).
 */
export function smoothstep(edge0: number, edge1: number, x: number): number {
  const t = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
  return t * t * (3 - 2 * t);
}
