import { ChunkQuadtree } from './chunkQuadtree';
import type { Plane } from './frustumMath';
import { BAND_STEPS, bandStart, bandStep, CHUNK_QUADS, CHUNK_SIZE, MAX_LOD_BANDS } from './lodBands';

/**
 * The step the grid's border chunks share with the first far ring (src/sim/lod/farRings.ts):
 * one vertex per chunk corner, 48 m, whatever their own band.
 */
export const BORDER_STEP = CHUNK_QUADS;

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
  /** Largest sideways move of a vertex (choppy waves): chunk boxes grow by this in x and z. */
  horizontalDisplacement?: number;
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
    this.bandCache = new Uint8Array(side * side);
    this.bandFrame = new Uint32Array(side * side);
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
      this.bands.fill(0, 0, this.total);
      this.edgeSteps.fill(bandStep(0), 0, this.total * 4);
      for (let k = 0; k < this.total; k++) {
        const i = k % side;
        const j = (k - i) / side;
        if (i === 0) this.edgeSteps[k * 4] = BORDER_STEP;
        if (i === side - 1) this.edgeSteps[k * 4 + 1] = BORDER_STEP;
        if (j === 0) this.edgeSteps[k * 4 + 2] = BORDER_STEP;
        if (j === side - 1) this.edgeSteps[k * 4 + 3] = BORDER_STEP;
      }
      this.lodCounts.fill(0);
      this.lodCounts[0] = this.total;
      return this.count;
    }
    this.count = this.quadtree.select(input.planes, originX, originZ, CHUNK_SIZE, -h, h, this.leaves, input.horizontalDisplacement ?? 0);
    this.prepareBands(input);
    this.lodCounts.fill(0);
    for (let n = 0; n < this.count; n++) {
      const leaf = this.leaves[n];
      const i = leaf % side;
      const j = (leaf - i) / side;
      const band = this.cachedBand(i, j);
      this.bands[n] = band;
      this.lodCounts[band]++;
      const own = BAND_STEPS[band];
      const o = n * 4;
      this.edgeSteps[o] = i > 0 ? Math.max(own, BAND_STEPS[this.cachedBand(i - 1, j)]) : BORDER_STEP;
      this.edgeSteps[o + 1] = i < side - 1 ? Math.max(own, BAND_STEPS[this.cachedBand(i + 1, j)]) : BORDER_STEP;
      this.edgeSteps[o + 2] = j > 0 ? Math.max(own, BAND_STEPS[this.cachedBand(i, j - 1)]) : BORDER_STEP;
      this.edgeSteps[o + 3] = j < side - 1 ? Math.max(own, BAND_STEPS[this.cachedBand(i, j + 1)]) : BORDER_STEP;
    }
    return this.count;
  }

  // Per-frame state of the band computation: bands are compared as squared distances
  // against squared band starts (no square root, no power), and each chunk's band is
  // computed once per frame although up to five chunks ask for it.
  private readonly startSquared = new Float64Array(MAX_LOD_BANDS);
  private readonly bandCache: Uint8Array;
  private readonly bandFrame: Uint32Array;
  private frame = 0;
  private bandCount = 1;
  private camX = 0;
  private camY = 0;
  private camZ = 0;
  private cellX = 0;
  private cellZ = 0;
  private boundsHeight = 0;

  private prepareBands(input: SelectionInput): void {
    this.frame = (this.frame + 1) >>> 0 || 1;
    this.bandCount = Math.max(1, Math.min(MAX_LOD_BANDS, Math.floor(input.lodBands)));
    for (let b = 1; b < this.bandCount; b++) this.startSquared[b] = bandStart(b, input.lodDistance) ** 2;
    this.camX = input.camera[0];
    this.camY = input.camera[1];
    this.camZ = input.camera[2];
    this.cellX = input.originX;
    this.cellZ = input.originZ;
    this.boundsHeight = input.maxDisplacement;
  }

  private cachedBand(i: number, j: number): number {
    const leaf = j * this.side + i;
    if (this.bandFrame[leaf] === this.frame) return this.bandCache[leaf];
    const band = this.computeBand(i, j);
    this.bandCache[leaf] = band;
    this.bandFrame[leaf] = this.frame;
    return band;
  }

  /** Band from the squared distance between the camera and the chunk's box. */
  private computeBand(i: number, j: number): number {
    const x0 = this.cellX + i * CHUNK_SIZE;
    const z0 = this.cellZ + j * CHUNK_SIZE;
    const x = this.camX;
    const z = this.camZ;
    const y = this.camY;
    const h = this.boundsHeight;
    const dx = x < x0 ? x0 - x : x > x0 + CHUNK_SIZE ? x - x0 - CHUNK_SIZE : 0;
    const dy = y > h ? y - h : y < -h ? -h - y : 0;
    const dz = z < z0 ? z0 - z : z > z0 + CHUNK_SIZE ? z - z0 - CHUNK_SIZE : 0;
    const d2 = dx * dx + dy * dy + dz * dz;
    let band = 0;
    while (band + 1 < this.bandCount && d2 >= this.startSquared[band + 1]) band++;
    return band;
  }
}
