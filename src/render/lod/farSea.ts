import { BufferAttribute, BufferGeometry, DynamicDrawUsage, Mesh, type Object3D } from 'three';
import { ChunkBatch } from './chunkBatch';
import type { DisplacementBounds } from '../../sim/waves/waveModel';
import { OCEAN_EXTENT } from '../../sim/lod/chunkSelection';
import { squareGrid } from '../../sim/lod/chunkGrid';
import { FarRingSelector, RING_CELL_QUADS, RING_OWN_STEP, ringEdgeSteps, SKIRT_RADIUS, skirtMesh } from '../../sim/lod/farRings';
import { classifyBox, OUTSIDE, type Plane } from '../../sim/lod/frustumMath';
import { MAX_LOD_BANDS } from '../../sim/lod/lodBands';
import type { OceanMaterial } from '../ocean/oceanMaterial';

/**
 * The sea beyond the chunk grid, out to the horizon (src/sim/lod/farRings.ts): the far rings'
 * cells in view, and the skirt past the last ring. Both draw with the chunks' material and
 * vertex shader, and after the sky: they may lie at the far plane itself.
 */
export class FarSea {
  private readonly selector = new FarRingSelector(OCEAN_EXTENT / 2);
  /** Every far ring's cell draws one shared grid: one draw for all of them. */
  readonly cells: ChunkBatch<OceanMaterial>;
  private readonly skirt: Mesh<BufferGeometry, OceanMaterial>;
  /** The skirt's vertices, x and z relative to the grid's centre. */
  private readonly skirtPoints: Float64Array;
  private readonly edgeScratch = [0, 0, 0, 0];

  constructor(
    private readonly material: OceanMaterial,
    parent: Object3D,
  ) {
    this.cells = new ChunkBatch(squareGrid(RING_OWN_STEP, RING_CELL_QUADS, true), material, this.selector.total);
    // The rings have already been culled by their quadtrees.
    this.cells.mesh.frustumCulled = false;
    parent.add(this.cells.mesh);
    // The skirt's vertices carry their world place in aChunk (grid position 0), updated as the grid moves.
    const rings = this.selector.rings;
    const { points, indices } = skirtMesh(rings[rings.length - 1]);
    this.skirtPoints = points;
    const count = points.length / 2;
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(count * 3), 3));
    geometry.setAttribute('aChunk', new BufferAttribute(new Float32Array(count * 4), 4).setUsage(DynamicDrawUsage));
    geometry.setAttribute('aEdgeSteps', new BufferAttribute(new Float32Array(count * 4).fill(1), 4));
    geometry.setAttribute('aTile', new BufferAttribute(new Float32Array(count * 2), 2));
    geometry.setIndex(new BufferAttribute(indices, 1));
    this.skirt = new Mesh(geometry, material);
    this.skirt.frustumCulled = false;
    parent.add(this.skirt);
  }

  /** Far ring cells chosen by the last update. */
  get cellsInView(): number {
    return this.selector.count;
  }

  /** The far rings' cells in view of `planes`, and the skirt, around the grid's centre. */
  update(planes: readonly Plane[], centerX: number, centerZ: number, bounds: DisplacementBounds): void {
    this.material.setOceanCenter(centerX, centerZ);
    const far = this.selector;
    const rings = far.rings;
    const count = far.select(planes, centerX, centerZ, -bounds.vertical, bounds.vertical, bounds.horizontal);
    const cells = this.cells;
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
    this.placeSkirt(planes, centerX, centerZ);
  }

  dispose(): void {
    this.cells.dispose();
    this.skirt.geometry.dispose();
  }

  /** Shows the skirt when the box of any of its four sides is in view, and moves it with the grid's centre. */
  private placeSkirt(planes: readonly Plane[], centerX: number, centerZ: number): void {
    const rings = this.selector.rings;
    const e = rings[rings.length - 1].outer;
    const R = SKIRT_RADIUS;
    let seen = false;
    for (const [x0, z0, x1, z1] of [
      [-R, e, R, R],
      [-R, -R, R, -e],
      [e, -R, R, R],
      [-R, -R, -e, R],
    ]) {
      if (classifyBox(planes, centerX + x0, 0, centerZ + z0, centerX + x1, 0, centerZ + z1) !== OUTSIDE) seen = true;
    }
    this.skirt.visible = seen;
    const skirtChunk = this.skirt.geometry.getAttribute('aChunk') as BufferAttribute;
    const data = skirtChunk.array as Float32Array;
    const points = this.skirtPoints;
    // Rewritten only when the grid's centre moved (compared as the buffer stores it).
    if (data[0] !== Math.fround(centerX + points[0]) || data[1] !== Math.fround(centerZ + points[1])) {
      for (let v = 0; v < points.length / 2; v++) {
        data[v * 4] = centerX + points[v * 2];
        data[v * 4 + 1] = centerZ + points[v * 2 + 1];
        // Band index past the last ring's, for the LOD colours.
        data[v * 4 + 2] = MAX_LOD_BANDS + rings.length;
        data[v * 4 + 3] = 1;
      }
      skirtChunk.needsUpdate = true;
    }
  }
}
