import { BAND_STEPS, bandQuads } from './lodBands';

/**
 * One band's shared chunk grid: vertices every `step` full-resolution quads, stored as
 * integer grid coordinates (x, 0, z) that the vertex shader scales and places; triangles
 * counter-clockwise seen from above (+y), so the front face looks up.
 */
export function chunkGrid(band: number): { positions: Float32Array; indices: Uint16Array } {
  return squareGrid(BAND_STEPS[band], bandQuads(band));
}

/**
 * `quads` × `quads` quads with vertices every `step` grid units (the far rings' cells use it
 * too). With `cornerDiagonals`, the quads at the grid's corners (0, 0) and (quads−1, quads−1)
 * are split along the diagonal through the grid's corner: when both sides meeting there are
 * snapped to a coarser step, the usual diagonal would leave a vertex on the edge of the
 * one big triangle the snapping makes (a T-junction); this one keeps the edges shared.
 */
export function squareGrid(step: number, quads: number, cornerDiagonals = false): { positions: Float32Array; indices: Uint16Array } {
  const perSide = quads + 1;
  const positions = new Float32Array(perSide * perSide * 3);
  for (let j = 0; j < perSide; j++) {
    for (let i = 0; i < perSide; i++) {
      const o = (j * perSide + i) * 3;
      positions[o] = i * step;
      positions[o + 2] = j * step;
    }
  }
  const indices = new Uint16Array(quads * quads * 6);
  let k = 0;
  for (let j = 0; j < quads; j++) {
    for (let i = 0; i < quads; i++) {
      const a = j * perSide + i;
      const b = a + 1;
      const c = a + perSide;
      const d = c + 1;
      const corner = cornerDiagonals && i === j && (i === 0 || i === quads - 1);
      indices.set(corner ? [a, c, d, a, d, b] : [a, c, b, b, c, d], k);
      k += 6;
    }
  }
  return { positions, indices };
}
