import { describe, expect, it } from 'vitest';
import { BufferAttribute, InstancedBufferGeometry, MeshBasicMaterial } from 'three';
import { ChunkBatch, EXPANDED_UP_TO_VERTICES } from '../../../../src/render/lod/chunkBatch';
import { chunkGrid, squareGrid } from '../../../../src/sim/lod/chunkGrid';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

type Vertex = number[];

/**
 * What the draw hands the vertex shader, triangle by triangle: for every index drawn, the
 * vertex's grid position and its record (aChunk, aEdgeSteps, aTile), resolved the way WebGL
 * does for an instanced draw (records per instance) or a plain one (records per vertex).
 */
function drawnVertices(batch: ChunkBatch<MeshBasicMaterial>): Vertex[] {
  const geometry = batch.mesh.geometry;
  const index = geometry.getIndex()!.array;
  const read = (name: string, i: number) => {
    const a = geometry.getAttribute(name) as BufferAttribute;
    return Array.from(a.array.subarray(i * a.itemSize, (i + 1) * a.itemSize));
  };
  const out: Vertex[] = [];
  if (geometry instanceof InstancedBufferGeometry) {
    for (let instance = 0; instance < geometry.instanceCount; instance++) {
      for (const i of index)
        out.push([...read('position', i), ...read('aChunk', instance), ...read('aEdgeSteps', instance), ...read('aTile', instance)]);
    }
    return out;
  }
  const { start, count } = geometry.drawRange;
  for (let k = start; k < start + count; k++) {
    const i = index[k];
    out.push([...read('position', i), ...read('aChunk', i), ...read('aEdgeSteps', i), ...read('aTile', i)]);
  }
  return out;
}

/** The same vertices, written straight from the grid and the records (the brute-force reference). */
function expectedVertices(grid: { positions: Float32Array; indices: Uint16Array }, records: number[][]): Vertex[] {
  const out: Vertex[] = [];
  for (const record of records) {
    for (const i of grid.indices) out.push([...grid.positions.subarray(i * 3, i * 3 + 3), ...record].map(Math.fround));
  }
  return out;
}

function randomRecords(seed: number, count: number): number[][] {
  const random = seededRandom(seed);
  return Array.from({ length: count }, () => [
    Math.round((random() - 0.5) * 4000),
    Math.round((random() - 0.5) * 4000),
    Math.floor(random() * 6),
    2,
    1 + Math.floor(random() * 24),
    1 + Math.floor(random() * 24),
    1 + Math.floor(random() * 24),
    1 + Math.floor(random() * 24),
    Math.floor(random() * 4) * 6,
    Math.floor(random() * 4) * 6,
  ]);
}

function fill(batch: ChunkBatch<MeshBasicMaterial>, records: number[][]): void {
  batch.clear();
  for (const r of records) batch.add(r[0], r[1], r[2], r[3], r.slice(4, 8), 0, r[8], r[9]);
  batch.commit();
}

describe('a chunk batch draws every chunk added, instanced or expanded', () => {
  const material = new MeshBasicMaterial();
  // Band 0 (625 vertices a chunk) is instanced; bands 2-5 and a far ring's cell are expanded.
  const grids = [0, 1, 2, 3, 4, 5].map((band) => ({ name: `band ${band}`, grid: chunkGrid(band) }));
  grids.push({ name: 'far cell', grid: squareGrid(4, 6, true) });

  it.each(grids)('$name: the vertices drawn are the grid under each record, in the order added (seeded cases)', ({ grid }) => {
    const batch = new ChunkBatch(grid, material, 1000);
    expect(batch.expanded).toBe(grid.positions.length / 3 <= EXPANDED_UP_TO_VERTICES);
    // Growing past the first capacity twice, shrinking, and empty: stale records must not be drawn.
    const counts = batch.expanded ? [37, 150, 9, 0, 300] : [3, 12, 2, 0, 5];
    for (const [seed, count] of counts.map((n, k) => [k + 1, n])) {
      const records = randomRecords(seed, count);
      fill(batch, records);
      expect(batch.mesh.visible).toBe(count > 0);
      expect(drawnVertices(batch).join('\n')).toBe(expectedVertices(grid, records).join('\n'));
      expect(Array.from({ length: count }, (_, n) => batch.record(n))).toEqual(records.map((r) => r.map(Math.fround)));
    }
    batch.dispose();
  });

  it('the small grids are expanded and band 0 instanced, so the default view draws each band in one draw', () => {
    expect(new ChunkBatch(chunkGrid(5), material, 10).expanded).toBe(true);
    expect(new ChunkBatch(chunkGrid(2), material, 10).expanded).toBe(true);
    expect(new ChunkBatch(chunkGrid(0), material, 10).expanded).toBe(false);
    expect(new ChunkBatch(chunkGrid(0), material, 10).mesh.geometry).toBeInstanceOf(InstancedBufferGeometry);
  });

  it('says no past maxChunks, keeping what it holds', () => {
    const batch = new ChunkBatch(chunkGrid(5), material, 3);
    const records = randomRecords(9, 5);
    batch.clear();
    const accepted = records.map((r) => batch.add(r[0], r[1], r[2], r[3], r.slice(4, 8), 0, r[8], r[9]));
    batch.commit();
    expect(accepted).toEqual([true, true, true, false, false]);
    expect(drawnVertices(batch)).toEqual(expectedVertices(chunkGrid(5), records.slice(0, 3)));
  });
});
