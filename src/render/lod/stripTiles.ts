import type { Object3D } from 'three';
import type { ChunkBatch } from './chunkBatch';
import { gridBandBatch } from './gridBandBatch';
import type { DisplacementBounds } from '../../sim/waves/waveModel';
import { squareGrid } from '../../sim/lod/chunkGrid';
import { classifyBox, INSIDE, OUTSIDE, type Plane } from '../../sim/lod/frustumMath';
import { BAND_STEPS, BASE_STEP, CHUNK_QUADS, CHUNK_SIZE, MAX_LOD_BANDS, bandQuads } from '../../sim/lod/lodBands';
import type { OceanMaterial } from '../ocean/oceanMaterial';

/**
 * compare=: a chunk that straddles its strip's frustum is drawn as TILES × TILES tiles, only
 * those that can reach the strip. A tile is the band's grid cut into squares: the same
 * integer grid points (offset by aTile inside the chunk, same aChunk), the same triangles in
 * the same vertex order, so every vertex is computed from the same numbers as in the whole
 * chunk and the strip's pixels are those of the model alone; a chunk straddling a divider
 * then costs each model only the tiles on its side. Bands whose chunks have fewer than TILES quads a side are drawn whole.
 */
const TILES = 4;
/** Tile instances a band can draw in one frame; past it, straddling chunks are drawn whole. */
const TILE_CAPACITY = 2048;
const tiledBand = (band: number) => band < MAX_LOD_BANDS && bandQuads(band) >= TILES && bandQuads(band) % TILES === 0;

/** A compare strip's tiles of the grid chunks that straddle its frustum, one batch per band that can be tiled. */
export class StripTiles {
  /** Per band: its tiles of straddling chunks (null where the band is always drawn whole). */
  readonly batches: (ChunkBatch<OceanMaterial> | null)[] = [];

  constructor(material: OceanMaterial, parent: Object3D) {
    for (let band = 0; band < MAX_LOD_BANDS; band++) {
      if (!tiledBand(band)) {
        this.batches.push(null);
        continue;
      }
      const batch = gridBandBatch(squareGrid(BAND_STEPS[band], bandQuads(band) / TILES), material, band, TILE_CAPACITY);
      batch.mesh.visible = false;
      this.batches.push(batch);
      parent.add(batch.mesh);
    }
  }

  clear(): void {
    for (const batch of this.batches) batch?.clear();
  }

  /**
   * A chunk of `band` at world corner (x0, z0) that straddles the frustum `planes`: adds the
   * tiles that can reach it and returns true; false (draw it whole) when it lies wholly
   * inside, its band is not tiled, or the band's tiles are full. A tile's box is grown by the
   * waves' reach and by how far morphing and edge snapping can move its vertices (half the
   * coarser of the next band's step and the chunk's edge steps, `edgeSteps[e … e + 3]`), so
   * no tile left out can put a triangle inside the frustum.
   */
  add(
    planes: readonly Plane[],
    band: number,
    x0: number,
    z0: number,
    edgeSteps: Uint8Array,
    e: number,
    bounds: DisplacementBounds,
  ): boolean {
    const batch = this.batches[band];
    if (!batch || batch.count + TILES * TILES > batch.maxChunks) return false;
    const h = bounds.horizontal;
    const v = bounds.vertical;
    if (classifyBox(planes, x0 - h, -v, z0 - h, x0 + CHUNK_SIZE + h, v, z0 + CHUNK_SIZE + h) === INSIDE) return false;
    const next = band + 1 < MAX_LOD_BANDS ? BAND_STEPS[band + 1] : 0;
    const shift = (Math.max(next, edgeSteps[e], edgeSteps[e + 1], edgeSteps[e + 2], edgeSteps[e + 3]) / 2) * BASE_STEP;
    const reach = h + shift + 0.05;
    const tileUnits = CHUNK_QUADS / TILES;
    const tileSize = tileUnits * BASE_STEP;
    for (let tj = 0; tj < TILES; tj++) {
      for (let ti = 0; ti < TILES; ti++) {
        const tx = x0 + ti * tileSize;
        const tz = z0 + tj * tileSize;
        if (classifyBox(planes, tx - reach, -v - 0.05, tz - reach, tx + tileSize + reach, v + 0.05, tz + tileSize + reach) === OUTSIDE)
          continue;
        batch.add(x0, z0, band, BASE_STEP, edgeSteps, e, ti * tileUnits, tj * tileUnits);
      }
    }
    return true;
  }

  commit(): void {
    for (const batch of this.batches) batch?.commit();
  }

  dispose(): void {
    for (const batch of this.batches) batch?.dispose();
  }
}
