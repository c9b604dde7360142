import {
  BufferAttribute,
  BufferGeometry,
  DynamicDrawUsage,
  InstancedBufferAttribute,
  InstancedBufferGeometry,
  Mesh,
  type Material,
} from 'three';

/** A chunk's grid: integer grid coordinates (x, 0, z) and its triangles (src/sim/lod/chunkGrid.ts). */
export interface ChunkGridData {
  positions: Float32Array;
  indices: Uint16Array;
}

/**
 * Chunks of at most this many vertices are drawn expanded (the grid repeated in one plain
 * draw) rather than instanced: a chunk this small costs little to write per vertex.
 * perf: on a GPU either way is cheap; a software rasterizer pays for each instance as for a draw
 * of its own, so this is for it (docs/performance.md, "Software rasterizer").
 */
export const EXPANDED_UP_TO_VERTICES = 100;

/** Chunks an expanded batch has room for at first; it doubles when a frame needs more. */
const FIRST_EXPANDED_CAPACITY = 64;

/**
 * One mesh that draws any number of copies of a chunk grid, each placed by its own record:
 * aChunk (world x, world z of the corner, band, metres per grid unit), aEdgeSteps (the steps
 * shared with the neighbours on −x, +x, −z, +z) and aTile (a tile's first grid point, compare
 * strips). The vertex shader reads the record as attributes either way.
 * - Instanced (grids of many vertices): one instance per chunk, records per instance.
 * - Expanded (grids of at most EXPANDED_UP_TO_VERTICES): the grid repeated in one plain indexed
 *   draw, every vertex carrying its chunk's record. The same vertices and triangles in the same
 *   order as the instances would draw them, so the same pixels, in one draw instead of one per
 *   chunk (see EXPANDED_UP_TO_VERTICES).
 * Fill with add() after clear(), then commit() uploads the used part only.
 */
export class ChunkBatch<M extends Material> {
  readonly mesh: Mesh<BufferGeometry, M>;
  readonly expanded: boolean;
  /** Chunks added since clear(). */
  count = 0;
  private capacity: number;
  private readonly verticesPerChunk: number;
  private chunkData!: Float32Array;
  private edgeData!: Float32Array;
  private tileData!: Float32Array;
  /** Whether a tile place other than (0, 0) was ever added; until then the tile data are all 0. */
  private tilesPlaced = false;

  /** `maxChunks`: the most a frame may add (add() says no past it). */
  constructor(
    private readonly grid: ChunkGridData,
    material: M,
    readonly maxChunks: number,
  ) {
    this.verticesPerChunk = grid.positions.length / 3;
    this.expanded = this.verticesPerChunk <= EXPANDED_UP_TO_VERTICES;
    this.capacity = this.expanded ? Math.min(FIRST_EXPANDED_CAPACITY, maxChunks) : maxChunks;
    this.mesh = new Mesh(this.makeGeometry(), material);
  }

  clear(): void {
    this.count = 0;
  }

  /** Adds one chunk's record; false when the batch already holds maxChunks. */
  add(x: number, z: number, band: number, unit: number, edges: ArrayLike<number>, e: number, tileX = 0, tileZ = 0): boolean {
    if (this.count >= this.maxChunks) return false;
    if (this.count === this.capacity) this.grow();
    const copies = this.expanded ? this.verticesPerChunk : 1;
    const first = this.count * copies;
    const chunk = this.chunkData;
    const edge = this.edgeData;
    // Tile places stay 0 in every batch but the compare strips' tile batches: zeros need no writing there.
    if (tileX !== 0 || tileZ !== 0) this.tilesPlaced = true;
    const tile = this.tilesPlaced ? this.tileData : null;
    const e0 = edges[e];
    const e1 = edges[e + 1];
    const e2 = edges[e + 2];
    const e3 = edges[e + 3];
    for (let v = first; v < first + copies; v++) {
      const o = v * 4;
      chunk[o] = x;
      chunk[o + 1] = z;
      chunk[o + 2] = band;
      chunk[o + 3] = unit;
      edge[o] = e0;
      edge[o + 1] = e1;
      edge[o + 2] = e2;
      edge[o + 3] = e3;
      if (tile) {
        tile[v * 2] = tileX;
        tile[v * 2 + 1] = tileZ;
      }
    }
    this.count++;
    return true;
  }

  /** Draws the chunks added since clear(), uploading only their records. */
  commit(): void {
    const geometry = this.mesh.geometry;
    const count = this.count;
    this.mesh.visible = count > 0;
    if (this.expanded) geometry.setDrawRange(0, count * this.grid.indices.length);
    else (geometry as InstancedBufferGeometry).instanceCount = count;
    if (count === 0) return;
    const records = count * (this.expanded ? this.verticesPerChunk : 1);
    // Tile places never written are the zeros the buffer was made with: nothing to upload.
    for (const name of this.tilesPlaced ? ['aChunk', 'aEdgeSteps', 'aTile'] : ['aChunk', 'aEdgeSteps']) {
      const attribute = geometry.getAttribute(name) as BufferAttribute;
      attribute.clearUpdateRanges();
      attribute.addUpdateRange(0, records * attribute.itemSize);
      attribute.needsUpdate = true;
    }
  }

  /** Chunk n's record as added: corner x, z, band, unit, the four edge steps, tile x, z. */
  record(n: number): number[] {
    const v = n * (this.expanded ? this.verticesPerChunk : 1);
    return [
      ...this.chunkData.subarray(v * 4, v * 4 + 4),
      ...this.edgeData.subarray(v * 4, v * 4 + 4),
      ...this.tileData.subarray(v * 2, v * 2 + 2),
    ];
  }

  dispose(): void {
    this.mesh.geometry.dispose();
  }

  /** Twice the room, the records so far kept; a new geometry (three makes new buffers for it). */
  private grow(): void {
    const kept = [this.chunkData, this.edgeData, this.tileData];
    this.capacity = Math.min(this.capacity * 2, this.maxChunks);
    this.mesh.geometry.dispose();
    this.mesh.geometry = this.makeGeometry();
    this.chunkData.set(kept[0]);
    this.edgeData.set(kept[1]);
    this.tileData.set(kept[2]);
  }

  private makeGeometry(): BufferGeometry {
    const { positions, indices } = this.grid;
    const records = this.capacity * (this.expanded ? this.verticesPerChunk : 1);
    this.chunkData = new Float32Array(records * 4);
    this.edgeData = new Float32Array(records * 4);
    this.tileData = new Float32Array(records * 2);
    let geometry: BufferGeometry;
    if (this.expanded) {
      const vertices = this.verticesPerChunk;
      const repeated = new Float32Array(records * 3);
      const repeatedIndices =
        records > 65536 ? new Uint32Array(this.capacity * indices.length) : new Uint16Array(this.capacity * indices.length);
      for (let c = 0; c < this.capacity; c++) {
        repeated.set(positions, c * vertices * 3);
        for (let k = 0; k < indices.length; k++) repeatedIndices[c * indices.length + k] = indices[k] + c * vertices;
      }
      geometry = new BufferGeometry();
      geometry.setAttribute('position', new BufferAttribute(repeated, 3));
      geometry.setIndex(new BufferAttribute(repeatedIndices, 1));
      geometry.setDrawRange(0, 0);
    } else {
      const instanced = new InstancedBufferGeometry();
      instanced.setAttribute('position', new BufferAttribute(positions, 3));
      instanced.setIndex(new BufferAttribute(indices, 1));
      instanced.instanceCount = 0;
      geometry = instanced;
    }
    const Record = this.expanded ? BufferAttribute : InstancedBufferAttribute;
    geometry.setAttribute('aChunk', new Record(this.chunkData, 4).setUsage(DynamicDrawUsage));
    geometry.setAttribute('aEdgeSteps', new Record(this.edgeData, 4).setUsage(DynamicDrawUsage));
    geometry.setAttribute('aTile', new Record(this.tileData, 2).setUsage(DynamicDrawUsage));
    return geometry;
  }
}
