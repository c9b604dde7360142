import {
  BufferAttribute,
  CameraHelper,
  DynamicDrawUsage,
  Frustum,
  Group,
  BufferGeometry,
  Matrix4,
  Mesh,
  Vector3,
  type PerspectiveCamera,
} from 'three';
import { ChunkBatch } from './chunkBatch';
import type { DisplacementBounds } from '../../sim/waves/waveModel';
import { ChunkSelector, OCEAN_EXTENT, oceanOrigin, type SelectionInput } from '../../sim/lod/chunkSelection';
import type { Plane } from '../../sim/lod/frustumMath';
import { BAND_STEPS, BASE_STEP, CHUNK_QUADS, CHUNK_SIZE, MAX_LOD_BANDS, bandHasDetailNormals, bandQuads } from '../../sim/lod/lodBands';
import { chunkGrid, squareGrid } from '../../sim/lod/chunkGrid';
import { FarRingSelector, RING_CELL_QUADS, RING_OWN_STEP, ringEdgeSteps, SKIRT_RADIUS, skirtMesh } from '../../sim/lod/farRings';
import { classifyBox, INSIDE, OUTSIDE } from '../../sim/lod/frustumMath';
import { morphZones } from '../../sim/lod/lodMorph';
import type { OceanMaterial } from './oceanMaterial';
import { SKY_RENDER_ORDER } from '../sky/skyBackground';

export interface LodSettings {
  lodDistance: number;
  lodBands: number;
  lodBruteForce: boolean;
  freezeCulling: boolean;
  /** Geomorphing between bands (src/sim/lod/lodMorph.ts). */
  lodMorph: boolean;
}

export interface ChunkStats {
  chunksTotal: number;
  chunksVisible: number;
  /** Cells of the far rings beyond the grid in view (src/sim/lod/farRings.ts). */
  farCellsVisible: number;
  /** Visible chunks per band, nearest band first. */
  lodCounts: number[];
}

/**
 * The grid bands' draw order: before the sky (skyBackground.ts SKY_RENDER_ORDER), so that the
 * sky is not shaded under them. Their depth is well below the far plane's (the grid reaches a
 * few kilometres).
 */
const NEAR_SEA_RENDER_ORDER = SKY_RENDER_ORDER - 1;

/** The material a grid band draws with (see bandHasDetailNormals). */
function bandMaterial(material: OceanMaterial, band: number): OceanMaterial {
  return bandHasDetailNormals(band) ? material : material.near;
}

/** A batch drawn with the grid bands' order (before the sky), culled by the quadtree, not by three. */
function seaBatch(grid: { positions: Float32Array; indices: Uint16Array }, material: OceanMaterial, maxChunks: number): ChunkBatch<OceanMaterial> {
  const batch = new ChunkBatch(grid, material, maxChunks);
  // The quadtree has already culled; three's test would use a stale, origin-sized sphere.
  batch.mesh.frustumCulled = false;
  batch.mesh.renderOrder = NEAR_SEA_RENDER_ORDER;
  return batch;
}

/**
 * compare=: a chunk that straddles its strip's frustum is drawn as TILES × TILES tiles, only
 * those that can reach the strip. A tile is the band's grid cut into squares: the same
 * integer grid points (offset by aTile inside the chunk, same aChunk), the same triangles in
 * the same vertex order, so every vertex is computed from the same numbers as in the whole
 * chunk and the strip's pixels are those of the model alone; a chunk straddling a divider
 * then costs each model only the tiles on its side (vertices are what SwiftShader spends
 * most on). Bands whose chunks have fewer than TILES quads a side are drawn whole.
 */
const TILES = 4;
/** Tile instances a band can draw in one frame; past it, straddling chunks are drawn whole. */
const TILE_CAPACITY = 2048;
const tiledBand = (band: number) => band < MAX_LOD_BANDS && bandQuads(band) >= TILES && bandQuads(band) % TILES === 0;

/** 6 planes × 4, the camera (3), the grid's origin (2), the two bounds, four settings and whether straddling chunks are tiled. */
const SELECTION_KEY_LENGTH = 36;

/**
 * The ocean as chunks: each frame the quadtree picks the chunks in view, each gets its
 * band, and every band is drawn as one batch of its shared grid (one draw call per band in
 * use; see ChunkBatch). No mesh, geometry or buffer is created per frame (an expanded batch
 * grows, rarely, when a frame needs more room than it had): only the used part of the
 * records is uploaded.
 */
export class OceanChunks {
  readonly group = new Group();
  private readonly selector = new ChunkSelector();
  /** Per band, its chunks drawn whole. */
  private readonly batches: ChunkBatch<OceanMaterial>[] = [];
  private readonly frustum = new Frustum();
  private readonly viewProjection = new Matrix4();
  private readonly planes: Plane[] = Array.from({ length: 6 }, () => ({ nx: 0, ny: 0, nz: 1, d: 0 }));
  private readonly cameraPosition = new Vector3();
  private readonly cullCamera: [number, number, number] = [0, 0, 0];
  private bandsInUse = 1;
  /** Reused every frame; its planes, camera and origin are those culling uses. */
  private readonly selectionInput: SelectionInput = {
    planes: this.planes,
    camera: this.cullCamera,
    originX: 0,
    originZ: 0,
    maxDisplacement: 0,
    lodDistance: 1,
    lodBands: 1,
    bruteForce: false,
  };
  private frozenHelper: CameraHelper | null = null;
  private readonly farSelector = new FarRingSelector(OCEAN_EXTENT / 2);
  /** Every far ring's cell draws one shared grid: one draw for all of them. */
  private readonly farCells: ChunkBatch<OceanMaterial>;
  private readonly skirt: Mesh<BufferGeometry, OceanMaterial>;
  private readonly skirtPoints: Float64Array;
  private readonly edgeScratch = [0, 0, 0, 0];
  /** Everything the selection depends on, as of the last frame that selected: the planes, camera, origin, bounds and settings. */
  private readonly lastKey = new Float64Array(SELECTION_KEY_LENGTH).fill(NaN);
  /** The camera's position, quaternion, scale and projection matrix at the last culling capture (NaN: none yet). */
  private readonly lastCameraPose = new Float64Array(26).fill(NaN);
  private readonly key = new Float64Array(SELECTION_KEY_LENGTH);
  private readonly zones = new Float32Array(MAX_LOD_BANDS * 2);
  /** Per band: its tiles of chunks straddling a compare strip (null where the band is drawn whole). */
  private readonly tileBatches: (ChunkBatch<OceanMaterial> | null)[] = [];

  constructor(private readonly material: OceanMaterial) {
    const capacity = this.selector.total;
    for (let band = 0; band < MAX_LOD_BANDS; band++) {
      // Bands whose vertex normals keep their waves draw with the material compiled without
      // per-pixel detail normals (the same picture: their weight there is exactly 0).
      const batch = seaBatch(chunkGrid(band), bandMaterial(material, band), capacity);
      this.batches.push(batch);
      this.group.add(batch.mesh);
    }
    for (let band = 0; band < MAX_LOD_BANDS; band++) {
      if (!tiledBand(band)) {
        this.tileBatches.push(null);
        continue;
      }
      const batch = seaBatch(squareGrid(BAND_STEPS[band], bandQuads(band) / TILES), bandMaterial(material, band), TILE_CAPACITY);
      batch.mesh.visible = false;
      this.tileBatches.push(batch);
      this.group.add(batch.mesh);
    }
    this.farCells = new ChunkBatch(squareGrid(RING_OWN_STEP, RING_CELL_QUADS, true), material, this.farSelector.total);
    this.farCells.mesh.frustumCulled = false;
    this.group.add(this.farCells.mesh);
    // The skirt's vertices carry their world place in aChunk (grid position 0), updated as the grid moves.
    const rings = this.farSelector.rings;
    const { points, indices } = skirtMesh(rings[rings.length - 1]);
    this.skirtPoints = points;
    const count = points.length / 2;
    const skirtGeometry = new BufferGeometry();
    skirtGeometry.setAttribute('position', new BufferAttribute(new Float32Array(count * 3), 3));
    skirtGeometry.setAttribute('aChunk', new BufferAttribute(new Float32Array(count * 4), 4).setUsage(DynamicDrawUsage));
    skirtGeometry.setAttribute('aEdgeSteps', new BufferAttribute(new Float32Array(count * 4).fill(1), 4));
    skirtGeometry.setAttribute('aTile', new BufferAttribute(new Float32Array(count * 2), 2));
    skirtGeometry.setIndex(new BufferAttribute(indices, 1));
    this.skirt = new Mesh(skirtGeometry, material);
    this.skirt.frustumCulled = false;
    this.group.add(this.skirt);
  }

  /**
   * Chooses and uploads this frame's chunks for `camera` (or the frozen one).
   * `bounds`: how far the waves can move a vertex up or down and sideways (WaveModel.bounds()), metres.
   * `tiles` (a compare strip's camera): chunks straddling the frustum are drawn as the tiles that reach it (see TILES).
   */
  update(camera: PerspectiveCamera, settings: LodSettings, bounds: DisplacementBounds, tiles = false): void {
    this.setFrozen(settings.freezeCulling, camera);
    if (!this.frozenHelper) this.captureCullingView(camera);
    this.bandsInUse = settings.lodBruteForce ? 1 : settings.lodBands;
    const selector = this.selector;
    const input = this.selectionInput;
    input.maxDisplacement = bounds.vertical;
    input.horizontalDisplacement = bounds.horizontal;
    input.lodDistance = settings.lodDistance;
    input.lodBands = settings.lodBands;
    input.bruteForce = settings.lodBruteForce;
    // A still camera over an unchanged sea chooses the same chunks: the last frame's
    // selection and uploads stand, and the frame's CPU work is only this comparison.
    if (this.sameSelectionAsLastFrame(settings, tiles)) return;
    selector.select(input);
    this.material.setLodMorph(this.cullCamera, bounds.vertical, morphZones(settings.lodDistance, this.bandsInUse, settings.lodMorph, this.zones));
    for (const batch of this.batches) batch.clear();
    for (const batch of this.tileBatches) batch?.clear();
    const side = selector.side;
    const { originX, originZ } = input;
    for (let n = 0; n < selector.count; n++) {
      const band = selector.bands[n];
      const leaf = selector.leaves[n];
      const i = leaf % side;
      const j = (leaf - i) / side;
      const x = originX + i * CHUNK_SIZE;
      const z = originZ + j * CHUNK_SIZE;
      if (tiles && this.addTiles(band, x, z, selector.edgeSteps, n * 4, bounds)) continue;
      this.batches[band].add(x, z, band, BASE_STEP, selector.edgeSteps, n * 4);
    }
    for (const batch of this.tileBatches) batch?.commit();
    for (const batch of this.batches) batch.commit();
    this.updateFar(originX + OCEAN_EXTENT / 2, originZ + OCEAN_EXTENT / 2, bounds);
  }

  /**
   * A chunk of `band` at world corner (x0, z0) that straddles the frustum: adds the tiles that
   * can reach it to the band's tile mesh and returns true; false (draw it whole) when it lies
   * wholly inside, its band is not tiled, or the tile mesh is full. A tile's box is grown by
   * the waves' reach and by how far morphing and edge snapping can move its vertices (half
   * the coarser of the next band's step and the chunk's edge steps), so no tile left out can
   * put a triangle inside the frustum.
   */
  private addTiles(band: number, x0: number, z0: number, edgeSteps: Uint8Array, e: number, bounds: DisplacementBounds): boolean {
    const batch = this.tileBatches[band];
    if (!batch || batch.count + TILES * TILES > batch.maxChunks) return false;
    const h = bounds.horizontal;
    const v = bounds.vertical;
    if (classifyBox(this.planes, x0 - h, -v, z0 - h, x0 + CHUNK_SIZE + h, v, z0 + CHUNK_SIZE + h) === INSIDE) return false;
    const next = band + 1 < MAX_LOD_BANDS ? BAND_STEPS[band + 1] : 0;
    const shift = (Math.max(next, edgeSteps[e], edgeSteps[e + 1], edgeSteps[e + 2], edgeSteps[e + 3]) / 2) * BASE_STEP;
    const reach = h + shift + 0.05;
    const tileUnits = CHUNK_QUADS / TILES;
    const tileSize = tileUnits * BASE_STEP;
    for (let tj = 0; tj < TILES; tj++) {
      for (let ti = 0; ti < TILES; ti++) {
        const tx = x0 + ti * tileSize;
        const tz = z0 + tj * tileSize;
        if (classifyBox(this.planes, tx - reach, -v - 0.05, tz - reach, tx + tileSize + reach, v + 0.05, tz + tileSize + reach) === OUTSIDE) continue;
        batch.add(x0, z0, band, BASE_STEP, edgeSteps, e, ti * tileUnits, tj * tileUnits);
      }
    }
    return true;
  }

  private sameSelectionAsLastFrame(settings: LodSettings, tiles: boolean): boolean {
    const key = this.key;
    const input = this.selectionInput;
    let k = 0;
    for (const plane of this.planes) {
      key[k++] = plane.nx;
      key[k++] = plane.ny;
      key[k++] = plane.nz;
      key[k++] = plane.d;
    }
    key[k++] = this.cullCamera[0];
    key[k++] = this.cullCamera[1];
    key[k++] = this.cullCamera[2];
    key[k++] = input.originX;
    key[k++] = input.originZ;
    key[k++] = input.maxDisplacement;
    key[k++] = input.horizontalDisplacement ?? 0;
    key[k++] = settings.lodDistance;
    key[k++] = settings.lodBands;
    key[k++] = settings.lodBruteForce ? 1 : 0;
    key[k++] = settings.lodMorph ? 1 : 0;
    key[k++] = tiles ? 1 : 0;
    let same = true;
    for (let n = 0; n < SELECTION_KEY_LENGTH; n++) same &&= key[n] === this.lastKey[n];
    this.lastKey.set(key);
    return same;
  }

  /** Makes the next frame select again (after the GPU buffers were lost, for one). */
  forgetSelection(): void {
    this.lastKey.fill(NaN);
    this.lastCameraPose.fill(NaN);
  }

  /** The far rings' cells in view, and the skirt, around the grid's centre. */
  private updateFar(centerX: number, centerZ: number, bounds: DisplacementBounds): void {
    this.material.setOceanCenter(centerX, centerZ);
    const far = this.farSelector;
    const rings = far.rings;
    const count = far.select(this.planes, centerX, centerZ, -bounds.vertical, bounds.vertical, bounds.horizontal);
    const cells = this.farCells;
    const steps = this.edgeScratch;
    cells.clear();
    for (let n = 0; n < count; n++) {
      const r = far.ringOf[n];
      const ring = rings[r];
      const i = far.cellI[n];
      const j = far.cellJ[n];
      ringEdgeSteps(ring, i, j, r === rings.length - 1, steps);
      // Band index past the grid's six, for the LOD colours (the shader clamps to its last colour).
      cells.add(centerX - ring.outer + i * ring.cellSize, centerZ - ring.outer + j * ring.cellSize, MAX_LOD_BANDS + r, ring.unit, steps, 0);
    }
    cells.commit();
    // The skirt is drawn when the box of any of its four sides is in view.
    const e = rings[rings.length - 1].outer;
    const R = SKIRT_RADIUS;
    let skirtSeen = false;
    for (const [x0, z0, x1, z1] of [[-R, e, R, R], [-R, -R, R, -e], [e, -R, R, R], [-R, -R, -e, R]]) {
      if (classifyBox(this.planes, centerX + x0, 0, centerZ + z0, centerX + x1, 0, centerZ + z1) !== OUTSIDE) skirtSeen = true;
    }
    this.skirt.visible = skirtSeen;
    const skirtChunk = this.skirt.geometry.getAttribute('aChunk') as BufferAttribute;
    const data = skirtChunk.array as Float32Array;
    const points = this.skirtPoints;
    if (data[0] !== Math.fround(centerX + points[0]) || data[1] !== Math.fround(centerZ + points[1])) {
      for (let v = 0; v < points.length / 2; v++) {
        data[v * 4] = centerX + points[v * 2];
        data[v * 4 + 1] = centerZ + points[v * 2 + 1];
        data[v * 4 + 2] = MAX_LOD_BANDS + rings.length;
        data[v * 4 + 3] = 1;
      }
      skirtChunk.needsUpdate = true;
    }
  }

  private captureCullingView(camera: PerspectiveCamera): void {
    // A camera that has not moved since the last capture has the same frustum and origin, and
    // its world matrix is the one that capture made: the matrices need not be made again
    // (three's camera.updateMatrixWorld composes, decomposes and inverts: a sixth of the
    // paused default view's update step).
    if (this.sameCameraPose(camera)) return;
    camera.updateMatrixWorld();
    this.viewProjection.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    this.frustum.setFromProjectionMatrix(this.viewProjection);
    this.frustum.planes.forEach((plane, k) => {
      const target = this.planes[k];
      target.nx = plane.normal.x;
      target.ny = plane.normal.y;
      target.nz = plane.normal.z;
      target.d = plane.constant;
    });
    this.cameraPosition.setFromMatrixPosition(camera.matrixWorld).toArray(this.cullCamera);
    [this.selectionInput.originX, this.selectionInput.originZ] = oceanOrigin(this.cullCamera[0], this.cullCamera[2]);
  }

  /**
   * Whether the camera's own transform and projection are those of the last capture; records
   * them. A camera with a parent (whose world matrix also depends on the parent's) never counts
   * as unmoved.
   */
  private sameCameraPose(camera: PerspectiveCamera): boolean {
    const last = this.lastCameraPose;
    const { position: p, quaternion: q, scale: s } = camera;
    const projection = camera.projectionMatrix.elements;
    let same = camera.parent === null &&
      last[0] === p.x && last[1] === p.y && last[2] === p.z &&
      last[3] === q.x && last[4] === q.y && last[5] === q.z && last[6] === q.w &&
      last[7] === s.x && last[8] === s.y && last[9] === s.z;
    last[0] = p.x; last[1] = p.y; last[2] = p.z;
    last[3] = q.x; last[4] = q.y; last[5] = q.z; last[6] = q.w;
    last[7] = s.x; last[8] = s.y; last[9] = s.z;
    for (let i = 0; i < 16; i++) {
      same &&= last[10 + i] === projection[i];
      last[10 + i] = projection[i];
    }
    return same;
  }

  /**
   * "Freeze culling": keeps the frustum, position and origin of the moment it was switched
   * on, and draws that frustum as lines (out to the ocean's edge), so orbiting away shows
   * from outside which chunks were chosen.
   */
  private setFrozen(frozen: boolean, camera: PerspectiveCamera): void {
    if (frozen === (this.frozenHelper !== null)) return;
    if (frozen) {
      this.captureCullingView(camera);
      const snapshot = camera.clone();
      snapshot.far = OCEAN_EXTENT / 2;
      snapshot.updateProjectionMatrix();
      snapshot.updateMatrixWorld();
      this.frozenHelper = new CameraHelper(snapshot);
      this.frozenHelper.update();
      this.group.add(this.frozenHelper);
    } else if (this.frozenHelper) {
      this.group.remove(this.frozenHelper);
      this.frozenHelper.dispose();
      this.frozenHelper = null;
    }
  }

  /** What each batch draws (bands, their tiles, then the far cells): its chunks' records (ChunkBatch.record), for tests. */
  drawnRecords(): number[][][] {
    const batches = [...this.batches, ...this.tileBatches, this.farCells];
    return batches.flatMap((batch) => (batch && batch.mesh.visible ? [Array.from({ length: batch.count }, (_, n) => batch.record(n))] : []));
  }

  stats(): ChunkStats {
    return {
      chunksTotal: this.selector.total,
      chunksVisible: this.selector.count,
      farCellsVisible: this.farSelector.count,
      lodCounts: this.selector.lodCounts.slice(0, this.bandsInUse),
    };
  }

  dispose(): void {
    for (const batch of this.batches) batch.dispose();
    for (const batch of this.tileBatches) batch?.dispose();
    this.farCells.dispose();
    this.skirt.geometry.dispose();
    this.frozenHelper?.dispose();
  }
}
