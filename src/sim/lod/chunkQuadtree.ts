import { classifyBox, INSIDE, OUTSIDE, type Plane } from './frustumMath';

/**
 * A quadtree over a square grid of `side × side` equal chunks, built once. Nodes hold index
 * ranges, not positions: the grid follows the camera, so boxes are made from the current
 * origin during traversal. Leaf index = j * side + i (i along x, j along z).
 */
export class ChunkQuadtree {
  readonly side: number;
  readonly leafCount: number;
  /** Per node: i0, j0, i1, j1 (half-open), first child, child count. */
  private readonly nodes: Int32Array;
  private nodeCount = 0;
  private readonly stack: Int32Array;

  constructor(side: number) {
    if (!Number.isInteger(side) || side < 1)
      throw new RangeError(`A chunk quadtree needs a whole number of chunks per side ≥ 1, got ${side}.`);
    this.side = side;
    this.leafCount = side * side;
    // A quadtree over n leaves has fewer than 2n nodes even when it splits in two along one axis.
    this.nodes = new Int32Array(2 * this.leafCount * 6);
    this.nodeCount = 1;
    this.fill(0, 0, 0, side, side);
    // Depth-first: at most three pending siblings per level plus the four just pushed.
    this.stack = new Int32Array(4 * (Math.ceil(Math.log2(side)) + 2));
  }

  /** Writes a node and, breadth-first per level, its children's slots, then fills them. */
  private fill(node: number, i0: number, j0: number, i1: number, j1: number): void {
    const o = node * 6;
    this.nodes.set([i0, j0, i1, j1, 0, 0], o);
    if (i1 - i0 === 1 && j1 - j0 === 1) return;
    const iMid = i1 - i0 > 1 ? (i0 + i1) >> 1 : i1;
    const jMid = j1 - j0 > 1 ? (j0 + j1) >> 1 : j1;
    const first = this.nodeCount;
    let count = 0;
    for (const [a0, a1] of [
      [i0, iMid],
      [iMid, i1],
    ]) {
      for (const [b0, b1] of [
        [j0, jMid],
        [jMid, j1],
      ]) {
        if (a1 > a0 && b1 > b0) count++;
      }
    }
    this.nodeCount += count;
    this.nodes[o + 4] = first;
    this.nodes[o + 5] = count;
    let c = 0;
    for (const [a0, a1] of [
      [i0, iMid],
      [iMid, i1],
    ]) {
      for (const [b0, b1] of [
        [j0, jMid],
        [jMid, j1],
      ]) {
        if (a1 > a0 && b1 > b0) this.fill(first + c++, a0, b0, a1, b1);
      }
    }
  }

  /**
   * The seed's frustum culling: from the root, a node wholly outside is skipped with its
   * subtree, a node wholly inside yields all its leaves untested, a straddling node recurses.
   * Chunk (i, j) spans x in [originX + i·size, originX + (i+1)·size], likewise z, and y in
   * [minY, maxY]; `margin` grows every box in x and z (vertices displaced sideways). Writes
   * leaf indices into `out` and returns how many.
   */
  select(
    planes: readonly Plane[],
    originX: number,
    originZ: number,
    size: number,
    minY: number,
    maxY: number,
    out: Uint32Array,
    margin = 0,
  ): number {
    const nodes = this.nodes;
    const side = this.side;
    const stack = this.stack;
    let top = 0;
    let count = 0;
    stack[top++] = 0;
    while (top > 0) {
      const o = stack[--top] * 6;
      const i0 = nodes[o];
      const j0 = nodes[o + 1];
      const i1 = nodes[o + 2];
      const j1 = nodes[o + 3];
      const x0 = originX + i0 * size - margin;
      const z0 = originZ + j0 * size - margin;
      const verdict = classifyBox(planes, x0, minY, z0, originX + i1 * size + margin, maxY, originZ + j1 * size + margin);
      if (verdict === OUTSIDE) continue;
      const childCount = nodes[o + 5];
      if (verdict === INSIDE || childCount === 0) {
        for (let j = j0; j < j1; j++) for (let i = i0; i < i1; i++) out[count++] = j * side + i;
        continue;
      }
      const first = nodes[o + 4];
      for (let c = 0; c < childCount; c++) stack[top++] = first + c;
    }
    return count;
  }
}
