import { ChunkQuadtree } from './chunkQuadtree';
import { classifyBox, OUTSIDE, type Plane } from './frustumMath';
import { OCEAN_EXTENT } from './chunkSelection';
import { CHUNK_QUADS, CHUNK_SIZE } from './lodBands';

/**
 * The sea beyond the 4 km chunk grid, out to the horizon: square rings of cells around
 * the grid, each ring's cells (and vertex spacing) twice the size of the previous ring's,
 * as in geometry clipmaps and CDLOD, so a triangle keeps about the same size on screen
 * at any distance. Past the last ring a skirt of 64 triangles runs out to SKIRT_RADIUS.
 *
 * Every ring cell draws one shared grid of RING_CELL_QUADS × RING_CELL_QUADS quads. Its
 * vertices are given in the chunk grid's units (CHUNK_QUADS across a cell, vertex step
 * RING_OWN_STEP), so the chunks' vertex shader and edge snapping serve both: a cell's
 * "unit" is its size / CHUNK_QUADS metres.
 *
 * Layout. Ring 1's vertex step is one chunk (48 m), and the grid's border chunks snap
 * their outer sides to it. A ring of cells of size c around a square of half-size E is
 * one cell wide when E / c is odd and two when it is even: the next ring's cells (2c)
 * then tile its outer square again. From ring 4 on, E / c stays 2 and each ring doubles
 * the half-size. A ring's outer sides snap to the next ring's step (2 × its own), the last
 * ring's to its cell corners, where the skirt starts: every seam is watertight.
 *
 * The waves fade out over rings 1 and 2 (see FAR_FADE_START/END): their spacing of 48 m
 * and more would only sample the ripples at random, and flat far rings cannot show the
 * shift of their lattice when the grid's origin moves by a chunk.
 */

/** Quads along a ring cell's side; vertex step in the chunk grid's units. */
export const RING_CELL_QUADS = 6;
export const RING_OWN_STEP = CHUNK_QUADS / RING_CELL_QUADS;
/**
 * Rings. With nine the last ends 295 km from the grid's centre, where its 12 km triangles
 * are about one pixel tall from 10 km up in a 720-pixel-high frame (12288 m × 10 km / (200 km)²
 * ≈ 3 mrad, a pixel being 1.3 mrad): beyond that only the skirt.
 */
export const FAR_RING_COUNT = 9;
/** Where the skirt ends, metres from the grid's centre: with the camera's far plane past it. */
export const SKIRT_RADIUS = 1e8;

/**
 * The waves fade out between these Chebyshev distances from the grid's centre, metres:
 * from the grid's edge (so every chunk keeps its full waves and the seam matches) to the
 * end of ring 2.
 */
export const FAR_FADE_START = OCEAN_EXTENT / 2;
export const FAR_FADE_END = farRings(FAR_FADE_START, 2)[1].outer;

export interface FarRing {
  /** Cell side, metres. */
  cellSize: number;
  /** Half-sizes of the ring's inner and outer squares, metres from the grid's centre. */
  inner: number;
  outer: number;
  /** Cells along the outer square's side, and the ring's width in cells. */
  side: number;
  width: number;
  /** Metres per chunk-grid unit in this ring's cells. */
  unit: number;
}

export function farRings(innerHalfSize: number, count = FAR_RING_COUNT): FarRing[] {
  const rings: FarRing[] = [];
  let inner = innerHalfSize;
  let cellSize = RING_CELL_QUADS * CHUNK_SIZE;
  for (let k = 0; k < count; k++) {
    const m = inner / cellSize;
    if (!Number.isInteger(m)) throw new RangeError(`Ring ${k + 1}: half-size ${inner} m is not a whole number of ${cellSize} m cells.`);
    const width = m % 2 === 1 ? 1 : 2;
    const outer = inner + width * cellSize;
    rings.push({ cellSize, inner, outer, side: (2 * outer) / cellSize, width, unit: cellSize / CHUNK_QUADS });
    inner = outer;
    cellSize *= 2;
  }
  return rings;
}

/** Whether cell (i, j) of a ring lies in its hole (the squares inside it). */
export function inRingHole(ring: FarRing, i: number, j: number): boolean {
  const lo = ring.width;
  const hi = ring.side - ring.width;
  return i >= lo && i < hi && j >= lo && j < hi;
}

/**
 * Steps, in the cell's grid units, that a ring cell's sides −x, +x, −z, +z share with
 * their neighbours: its own inside the ring and on its inner border (the finer side snaps
 * onto it), the next ring's on its outer border, and only its corners on the last ring's.
 */
export function ringEdgeSteps(ring: FarRing, i: number, j: number, last: boolean, out: number[] | Uint8Array, offset = 0): void {
  const outerStep = last ? CHUNK_QUADS : 2 * RING_OWN_STEP;
  const end = ring.side - 1;
  out[offset] = i === 0 ? outerStep : RING_OWN_STEP;
  out[offset + 1] = i === end ? outerStep : RING_OWN_STEP;
  out[offset + 2] = j === 0 ? outerStep : RING_OWN_STEP;
  out[offset + 3] = j === end ? outerStep : RING_OWN_STEP;
}

/**
 * Each frame's ring cells in view: one quadtree per ring over its full square of cells
 * (the seed's culling, unchanged), whose hole leaves are then dropped. Arrays sized once.
 */
export class FarRingSelector {
  readonly rings: FarRing[];
  private readonly trees: ChunkQuadtree[];
  private readonly scratch: Uint32Array;
  /** Per selected cell: ring index, i, j. */
  readonly ringOf: Uint8Array;
  readonly cellI: Uint16Array;
  readonly cellJ: Uint16Array;
  readonly total: number;
  count = 0;

  constructor(innerHalfSize: number, count = FAR_RING_COUNT) {
    this.rings = farRings(innerHalfSize, count);
    this.trees = this.rings.map((r) => new ChunkQuadtree(r.side));
    const most = Math.max(...this.rings.map((r) => r.side * r.side));
    this.scratch = new Uint32Array(most);
    this.total = this.rings.reduce((sum, r) => sum + r.side * r.side - (r.side - 2 * r.width) ** 2, 0);
    this.ringOf = new Uint8Array(this.total);
    this.cellI = new Uint16Array(this.total);
    this.cellJ = new Uint16Array(this.total);
  }

  /**
   * Cells in view around a grid centred at (centerX, centerZ), boxes spanning y in
   * [minY, maxY] and grown by `margin` in x and z (a wave model's sideways displacement).
   */
  select(planes: readonly Plane[], centerX: number, centerZ: number, minY: number, maxY: number, margin = 0): number {
    let count = 0;
    for (let r = 0; r < this.rings.length; r++) {
      const ring = this.rings[r];
      // Rings past the fade are flat: their boxes need no room for waves.
      const flat = ring.inner >= FAR_FADE_END;
      const found = this.trees[r].select(
        planes,
        centerX - ring.outer,
        centerZ - ring.outer,
        ring.cellSize,
        flat ? 0 : minY,
        flat ? 0 : maxY,
        this.scratch,
        flat ? 0 : margin,
      );
      for (let n = 0; n < found; n++) {
        const leaf = this.scratch[n];
        const i = leaf % ring.side;
        const j = (leaf - i) / ring.side;
        if (inRingHole(ring, i, j)) continue;
        this.ringOf[count] = r;
        this.cellI[count] = i;
        this.cellJ[count] = j;
        count++;
      }
    }
    this.count = count;
    return count;
  }
}

/** Whether a ring cell's box is outside the frustum: the brute-force twin of select(), for tests. */
export function ringCellOutside(
  planes: readonly Plane[],
  ring: FarRing,
  i: number,
  j: number,
  centerX: number,
  centerZ: number,
  minY: number,
  maxY: number,
  margin = 0,
): boolean {
  const flat = ring.inner >= FAR_FADE_END;
  const m = flat ? 0 : margin;
  const x0 = centerX - ring.outer + i * ring.cellSize - m;
  const z0 = centerZ - ring.outer + j * ring.cellSize - m;
  const size = ring.cellSize + 2 * m;
  return classifyBox(planes, x0, flat ? 0 : minY, z0, x0 + size, flat ? 0 : maxY, z0 + size) === OUTSIDE;
}

/**
 * The skirt: for each side of the last ring's outer square, one quad per cell from the
 * cell corners out to SKIRT_RADIUS along rays from the centre (rays never cross, so the
 * quads never overlap). Positions relative to the grid's centre, (x, z) pairs; indices
 * counter-clockwise seen from above.
 */
export function skirtMesh(last: FarRing, radius = SKIRT_RADIUS): { points: Float64Array; indices: Uint16Array } {
  const perSide = last.side;
  const e = last.outer;
  const ring: [number, number][] = [];
  // Walk the square's corners in one turning sense: along +z's side towards +x, then down +x's side.
  for (let k = 0; k < perSide; k++) ring.push([-e + k * last.cellSize, e]);
  for (let k = 0; k < perSide; k++) ring.push([e, e - k * last.cellSize]);
  for (let k = 0; k < perSide; k++) ring.push([e - k * last.cellSize, -e]);
  for (let k = 0; k < perSide; k++) ring.push([-e, -e + k * last.cellSize]);
  const n = ring.length;
  const points = new Float64Array(n * 4);
  ring.forEach(([x, z], k) => {
    points.set([x, z, (x / e) * radius, (z / e) * radius], k * 4);
  });
  const indices = new Uint16Array(n * 6);
  for (let k = 0; k < n; k++) {
    const a = 2 * k;
    const b = 2 * ((k + 1) % n);
    indices.set([a, a + 1, b, b, a + 1, b + 1], k * 6);
  }
  return { points, indices };
}
