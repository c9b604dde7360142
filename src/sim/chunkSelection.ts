import { ChunkQuadtree } from './chunkQuadtree';
import { distanceToBox, type Plane } from './frustumMath';
import { bandForDistance, bandStep, CHUNK_SIZE, MAX_LOD_BANDS } from './lodBands';

/** Chunks along each side of the ocean: 84 × 48 m = 4032 m. */
export const OCEAN_CHUNKS_PER_SIDE = 84;
export const OCEAN_EXTENT = OCEAN_CHUNKS_PER_SIDE * CHUNK_SIZE;

/**
 * The ocean's south-west corner for a camera at (x, z). Snapping to whole chunks (a
 * multiple of the coarsest band's step) keeps every vertex of every band on one world
 * lattice, so the waves stay put under a moving camera instead of swimming.
 */
export function oceanOrigin(cameraX: number, cameraZ: number): [number, number] {
  const half = (OCEAN_CHUNKS_PER_SIDE / 2) * CHUNK_SIZE;
  return [Math.round(cameraX / CHUNK_SIZE) * CHUNK_SIZE - half, Math.round(cameraZ / CHUNK_SIZE) * CHUNK_SIZE - half];
}

export interface SelectionInput {
  planes: readonly Plane[];
  camera: readonly [number, number, number];
  originX: number;
  originZ: number;
  /** Largest |height| of the surface: chunk boxes span y in [-this, +this]. */
  maxDisplacement: number;
  lodDistance: number;
  lodBands: number;
  /** Every chunk at full resolution and none culled: the reference the LOD is measured against. */
  bruteForce?: boolean;
}

/**
 * Each frame's chunks: which are in view (quadtree culling), each one's band (distance to
 * its nearest point, so height above the sea counts), and per side the step shared with
 * the neighbour (the coarser of the two) that the vertex shader snaps edge vertices to.
 * All arrays are allocated once; `select` fills the first `count` entries.
 */
export class ChunkSelector {
  readonly quadtree: ChunkQuadtree;
  readonly side: number;
  readonly leaves: Uint32Array;
  readonly bands: Uint8Array;
  /** Four per chunk: sides −x, +x, −z, +z, in full-resolution quads. */
  readonly edgeSteps: Uint8Array;
  readonly lodCounts = new Array<number>(MAX_LOD_BANDS).fill(0);
  count = 0;

  constructor(side = OCEAN_CHUNKS_PER_SIDE) {
    this.quadtree = new ChunkQuadtree(side);
    this.side = side;
    this.leaves = new Uint32Array(side * side);
    this.bands = new Uint8Array(side * side);
    this.edgeSteps = new Uint8Array(side * side * 4);
  }

  get total(): number {
    return this.side * this.side;
  }

  select(input: SelectionInput): number {
    const { originX, originZ, maxDisplacement: h } = input;
    const side = this.side;
    if (input.bruteForce) {
      for (let k = 0; k < this.total; k++) this.leaves[k] = k;
      this.count = this.total;
    } else {
      this.count = this.quadtree.select(input.planes, originX, originZ, CHUNK_SIZE, -h, h, this.leaves);
    }
    this.lodCounts.fill(0);
    for (let n = 0; n < this.count; n++) {
      const leaf = this.leaves[n];
      const i = leaf % side;
      const j = (leaf - i) / side;
      const band = input.bruteForce ? 0 : this.bandOf(input, i, j);
      this.bands[n] = band;
      this.lodCounts[band]++;
      const own = bandStep(band);
      const o = n * 4;
      if (input.bruteForce) {
        this.edgeSteps.fill(own, o, o + 4);
        continue;
      }
      this.edgeSteps[o] = i > 0 ? Math.max(own, bandStep(this.bandOf(input, i - 1, j))) : own;
      this.edgeSteps[o + 1] = i < side - 1 ? Math.max(own, bandStep(this.bandOf(input, i + 1, j))) : own;
      this.edgeSteps[o + 2] = j > 0 ? Math.max(own, bandStep(this.bandOf(input, i, j - 1))) : own;
      this.edgeSteps[o + 3] = j < side - 1 ? Math.max(own, bandStep(this.bandOf(input, i, j + 1))) : own;
    }
    return this.count;
  }

  /** The band of chunk (i, j), whether or not it is in view (neighbours need it too). */
  bandOf(input: SelectionInput, i: number, j: number): number {
    const [cx, cy, cz] = input.camera;
    const x0 = input.originX + i * CHUNK_SIZE;
    const z0 = input.originZ + j * CHUNK_SIZE;
    const h = input.maxDisplacement;
    const distance = distanceToBox(cx, cy, cz, x0, -h, z0, x0 + CHUNK_SIZE, h, z0 + CHUNK_SIZE);
    return bandForDistance(distance, input.lodDistance, input.lodBands);
  }
}
