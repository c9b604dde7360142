import { ChunkBatch, type ChunkGridData } from './chunkBatch';
import { bandHasDetailNormals } from '../../sim/lod/lodBands';
import type { OceanMaterial } from '../ocean/oceanMaterial';
import { SKY_RENDER_ORDER } from '../sky/skyBackground';

/**
 * The grid bands' draw order: before the sky (skyBackground.ts SKY_RENDER_ORDER), so that the
 * sky is not shaded under them. Their depth is well below the far plane's (the grid reaches a
 * few kilometres).
 */
const NEAR_SEA_RENDER_ORDER = SKY_RENDER_ORDER - 1;

/**
 * A batch of grid band `band`'s chunks (whole, or a compare strip's tiles of them), drawn
 * before the sky and culled by the quadtree, not by three. Bands whose vertex normals keep
 * their waves draw with the material compiled without per-pixel detail normals (the same
 * picture: their weight there is exactly 0).
 */
export function gridBandBatch(grid: ChunkGridData, material: OceanMaterial, band: number, maxChunks: number): ChunkBatch<OceanMaterial> {
  const batch = new ChunkBatch(grid, bandHasDetailNormals(band) ? material : material.near, maxChunks);
  // The quadtree has already culled; three's test would use a stale, origin-sized sphere.
  batch.mesh.frustumCulled = false;
  batch.mesh.renderOrder = NEAR_SEA_RENDER_ORDER;
  return batch;
}
