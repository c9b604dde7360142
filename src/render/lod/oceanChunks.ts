import { Group, type PerspectiveCamera } from 'three';
import type { ChunkBatch } from './chunkBatch';
import { CullingView } from './cullingView';
import { FarSea } from './farSea';
import { gridBandBatch } from './gridBandBatch';
import { StripTiles } from './stripTiles';
import type { DisplacementBounds } from '../../sim/waves/waveModel';
import { ChunkSelector, OCEAN_EXTENT, type SelectionInput } from '../../sim/lod/chunkSelection';
import { BASE_STEP, CHUNK_QUADS, CHUNK_SIZE, MAX_LOD_BANDS, refinedEdgeStep } from '../../sim/lod/lodBands';
import { chunkGrid, squareGrid } from '../../sim/lod/chunkGrid';
import { morphZones } from '../../sim/lod/lodMorph';
import type { OceanMaterial } from '../ocean/oceanMaterial';

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

/** 6 planes × 4, the eye (3), the grid's origin (2), the two bounds, four settings and whether straddling chunks are tiled. */
const SELECTION_KEY_LENGTH = 36;

/**
 * The ocean as chunks: each frame the quadtree picks the chunks in view (CullingView), each
 * gets its band, and every band is drawn as one batch of its shared grid (one draw call per
 * band in use; see ChunkBatch); a compare strip draws the chunks across its edges as tiles
 * (StripTiles), and the far rings and skirt carry the sea to the horizon (FarSea). No mesh,
 * geometry or buffer is created per frame (an expanded batch grows, rarely, when a frame
 * needs more room than it had): only the used part of the records is uploaded.
 */
export class OceanChunks {
  readonly group = new Group();
  private readonly selector = new ChunkSelector();
  private readonly view = new CullingView(this.group);
  /** Per band, its chunks drawn whole. */
  private readonly batches: ChunkBatch<OceanMaterial>[] = [];
  private readonly tiles: StripTiles;
  private readonly far: FarSea;
  private bandsInUse = 1;
  /** Reused every frame; its planes, eye and origin are the culling view's. */
  private readonly selectionInput: SelectionInput = {
    planes: this.view.planes,
    camera: this.view.eye,
    originX: 0,
    originZ: 0,
    maxDisplacement: 0,
    lodDistance: 1,
    lodBands: 1,
    bruteForce: false,
  };
  /** Everything the selection depends on, as of the last frame that selected: the planes, eye, origin, bounds and settings. */
  private readonly lastKey = new Float64Array(SELECTION_KEY_LENGTH).fill(NaN);
  private readonly key = new Float64Array(SELECTION_KEY_LENGTH);
  private readonly zones = new Float32Array(MAX_LOD_BANDS * 2);
  /**
   * The nearest band's chunks with each quad split `refine` times per side, by refinement,
   * made the first time a sea asks for it (update's `refine`), and those chunks' edge steps in
   * their own units.
   */
  private readonly refined = new Map<number, ChunkBatch<OceanMaterial>>();
  private readonly refinedEdges = new Float32Array(4);

  constructor(private readonly material: OceanMaterial) {
    const capacity = this.selector.total;
    for (let band = 0; band < MAX_LOD_BANDS; band++) {
      const batch = gridBandBatch(chunkGrid(band), material, band, capacity);
      this.batches.push(batch);
      this.group.add(batch.mesh);
    }
    this.tiles = new StripTiles(material, this.group);
    this.far = new FarSea(material, this.group);
  }

  /**
   * Chooses and uploads this frame's chunks for `camera` (or the frozen one).
   * `bounds`: how far the waves can move a vertex up or down and sideways (WaveModel.bounds()), metres.
   * `tiles` (a compare strip's camera): chunks straddling the frustum are drawn as the tiles that reach it (see StripTiles).
   * `refine`: how many times per side the nearest band's quads are split (src/sim/lod/lodBands.ts
   * nearBandRefinement), for a sea whose short steep waves the 2 m grid cannot draw. A compare
   * strip draws its split chunks whole rather than as tiles, so it draws them as the model alone does.
   */
  update(camera: PerspectiveCamera, settings: LodSettings, bounds: DisplacementBounds, tiles = false, refine = 1): void {
    const view = this.view;
    view.update(camera, settings.freezeCulling);
    this.bandsInUse = settings.lodBruteForce ? 1 : settings.lodBands;
    const selector = this.selector;
    const input = this.selectionInput;
    input.originX = view.originX;
    input.originZ = view.originZ;
    input.maxDisplacement = bounds.vertical;
    input.horizontalDisplacement = bounds.horizontal;
    input.lodDistance = settings.lodDistance;
    input.lodBands = settings.lodBands;
    input.bruteForce = settings.lodBruteForce;
    // A still camera over an unchanged sea chooses the same chunks: the last frame's
    // selection and uploads stand, and the frame's CPU work is only this comparison.
    if (this.sameSelectionAsLastFrame(settings, tiles, refine)) return;
    selector.select(input);
    this.material.setLodMorph(view.eye, bounds.vertical, morphZones(settings.lodDistance, this.bandsInUse, settings.lodMorph, this.zones));
    for (const batch of [...this.batches, ...this.refined.values()]) batch.clear();
    this.tiles.clear();
    const nearBand = refine > 1 ? this.refinedBatch(refine) : this.batches[0];
    const side = selector.side;
    const { originX, originZ } = input;
    for (let n = 0; n < selector.count; n++) {
      const band = selector.bands[n];
      const leaf = selector.leaves[n];
      const i = leaf % side;
      const j = (leaf - i) / side;
      const x = originX + i * CHUNK_SIZE;
      const z = originZ + j * CHUNK_SIZE;
      const split = band === 0 && refine > 1;
      if (tiles && !split && this.tiles.add(view.planes, band, x, z, selector.edgeSteps, n * 4, bounds)) continue;
      if (split) {
        for (let e = 0; e < 4; e++) this.refinedEdges[e] = refinedEdgeStep(selector.edgeSteps[n * 4 + e], refine);
        nearBand.add(x, z, 0, BASE_STEP / refine, this.refinedEdges, 0);
      } else this.batches[band].add(x, z, band, BASE_STEP, selector.edgeSteps, n * 4);
    }
    this.tiles.commit();
    for (const batch of [...this.batches, ...this.refined.values()]) batch.commit();
    this.far.update(view.planes, originX + OCEAN_EXTENT / 2, originZ + OCEAN_EXTENT / 2, bounds);
  }

  private refinedBatch(refine: number): ChunkBatch<OceanMaterial> {
    let batch = this.refined.get(refine);
    if (!batch) {
      batch = gridBandBatch(squareGrid(1, CHUNK_QUADS * refine), this.material, 0, this.selector.total);
      this.refined.set(refine, batch);
      this.group.add(batch.mesh);
    }
    return batch;
  }

  private sameSelectionAsLastFrame(settings: LodSettings, tiles: boolean, refine: number): boolean {
    const key = this.key;
    const { planes, eye } = this.view;
    const input = this.selectionInput;
    let k = 0;
    for (const plane of planes) {
      key[k++] = plane.nx;
      key[k++] = plane.ny;
      key[k++] = plane.nz;
      key[k++] = plane.d;
    }
    key[k++] = eye[0];
    key[k++] = eye[1];
    key[k++] = eye[2];
    key[k++] = input.originX;
    key[k++] = input.originZ;
    key[k++] = input.maxDisplacement;
    key[k++] = input.horizontalDisplacement ?? 0;
    key[k++] = settings.lodDistance;
    key[k++] = settings.lodBands;
    key[k++] = settings.lodBruteForce ? 1 : 0;
    key[k++] = settings.lodMorph ? 1 : 0;
    key[k++] = tiles ? refine : -refine;
    let same = true;
    for (let n = 0; n < SELECTION_KEY_LENGTH; n++) same &&= key[n] === this.lastKey[n];
    this.lastKey.set(key);
    return same;
  }

  /** Makes the next frame select again (after the GPU buffers were lost, for one). */
  forgetSelection(): void {
    this.lastKey.fill(NaN);
    this.view.forget();
  }

  /** What each batch draws (bands, their tiles, then the far cells): its chunks' records (ChunkBatch.record), for tests. */
  drawnRecords(): number[][][] {
    const batches = [...this.batches, ...this.refined.values(), ...this.tiles.batches, this.far.cells];
    return batches.flatMap((batch) =>
      batch && batch.mesh.visible ? [Array.from({ length: batch.count }, (_, n) => batch.record(n))] : [],
    );
  }

  stats(): ChunkStats {
    return {
      chunksTotal: this.selector.total,
      chunksVisible: this.selector.count,
      farCellsVisible: this.far.cellsInView,
      lodCounts: this.selector.lodCounts.slice(0, this.bandsInUse),
    };
  }

  dispose(): void {
    for (const batch of [...this.batches, ...this.refined.values()]) batch.dispose();
    this.tiles.dispose();
    this.far.dispose();
    this.view.dispose();
  }
}
