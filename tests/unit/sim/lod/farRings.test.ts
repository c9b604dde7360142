import { describe, expect, it } from 'vitest';
import { viewProjection } from '../../../support/cameraMath';
import { chunkGrid, squareGrid } from '../../../../src/sim/lod/chunkGrid';
import { BORDER_STEP, OCEAN_CHUNKS_PER_SIDE, OCEAN_EXTENT } from '../../../../src/sim/lod/chunkSelection';
import { snapGridVertex } from '../../../../src/sim/lod/edgeSnap';
import {
  FAR_FADE_END,
  FAR_RING_COUNT,
  FarRingSelector,
  farRings,
  inRingHole,
  RING_CELL_QUADS,
  RING_OWN_STEP,
  ringCellOutside,
  ringEdgeSteps,
  skirtMesh,
  type FarRing,
} from '../../../../src/sim/lod/farRings';
import { planesFromMatrix } from '../../../../src/sim/lod/frustumMath';
import { seededRandom } from '../../../../src/sim/noise/integerHash';
import { BASE_STEP, CHUNK_QUADS, MAX_LOD_BANDS } from '../../../../src/sim/lod/lodBands';

const HALF = OCEAN_EXTENT / 2;
type Point = [number, number];

/**
 * Every triangle of the grid's border chunks (coarsest band, outer sides snapped to the
 * border step) and of every ring cell, as the vertex shader places them, in metres from
 * the grid's centre.
 */
function drawnSea(rings: FarRing[], breakSeam = false): Point[][] {
  const triangles: Point[][] = [];
  const place = (grid: { positions: Float32Array; indices: Uint16Array }, x0: number, z0: number, unit: number, steps: number[]) => {
    const { positions, indices } = grid;
    for (let t = 0; t < indices.length; t += 3) {
      triangles.push(
        [0, 1, 2].map((c) => {
          const v = indices[t + c] * 3;
          const [si, sj] = snapGridVertex(positions[v], positions[v + 2], CHUNK_QUADS, steps);
          return [x0 + si * unit, z0 + sj * unit] as Point;
        }),
      );
    }
  };
  // The planted fault: border chunks one band finer whose outer sides keep their own step.
  const coarsest = chunkGrid(MAX_LOD_BANDS - (breakSeam ? 2 : 1));
  const n = OCEAN_CHUNKS_PER_SIDE;
  const step = BASE_STEP * CHUNK_QUADS;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const own = breakSeam ? CHUNK_QUADS / 2 : CHUNK_QUADS;
      const border = breakSeam ? own : BORDER_STEP;
      const steps = [i === 0 ? border : own, i === n - 1 ? border : own, j === 0 ? border : own, j === n - 1 ? border : own];
      place(coarsest, -HALF + i * step, -HALF + j * step, BASE_STEP, steps);
    }
  }
  const cell = squareGrid(RING_OWN_STEP, RING_CELL_QUADS, true);
  rings.forEach((ring, r) => {
    for (let j = 0; j < ring.side; j++) {
      for (let i = 0; i < ring.side; i++) {
        if (inRingHole(ring, i, j)) continue;
        const steps = [0, 0, 0, 0];
        ringEdgeSteps(ring, i, j, r === rings.length - 1, steps);
        place(cell, -ring.outer + i * ring.cellSize, -ring.outer + j * ring.cellSize, ring.unit, steps);
      }
    }
  });
  return triangles;
}

/** Problems of a set of triangles meant to tile the square of half-size `half` exactly. */
function tilingProblems(triangles: Point[][], half: number): string[] {
  const problems: string[] = [];
  const directed = new Map<string, number>();
  let area = 0;
  for (const [a, b, c] of triangles) {
    const signed = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    // Snapping collapses triangles to zero area: they draw nothing.
    if (signed === 0) continue;
    if (signed > 0) problems.push(`flipped ${a} ${b} ${c}`);
    area += Math.abs(signed) / 2;
    for (const [p, q] of [
      [a, b],
      [b, c],
      [c, a],
    ]) {
      if (p[0] === q[0] && p[1] === q[1]) continue;
      const key = `${p}|${q}`;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  }
  if (area !== (2 * half) ** 2) problems.push(`area ${area}, expected ${(2 * half) ** 2}`);
  for (const [key, count] of directed) {
    if (count !== 1) problems.push(`edge ${key} walked ${count} times`);
    if (directed.has(key.split('|').reverse().join('|'))) continue;
    const [p, q] = key.split('|').map((s) => s.split(',').map(Number));
    const onOutline = (p[0] === q[0] && Math.abs(p[0]) === half) || (p[1] === q[1] && Math.abs(p[1]) === half);
    if (!onOutline) problems.push(`open edge ${key}`);
  }
  return problems;
}

describe('far rings', () => {
  const rings = farRings(HALF);

  it('double their cells ring by ring and tile each outer square with whole cells', () => {
    expect(rings).toHaveLength(FAR_RING_COUNT);
    expect(rings[0]).toMatchObject({ inner: HALF, cellSize: RING_CELL_QUADS * BASE_STEP * CHUNK_QUADS });
    for (let r = 1; r < rings.length; r++) {
      expect(rings[r].cellSize).toBe(2 * rings[r - 1].cellSize);
      expect(rings[r].inner).toBe(rings[r - 1].outer);
    }
    for (const ring of rings) {
      expect(Number.isInteger((2 * ring.outer) / ring.cellSize)).toBe(true);
      expect(ring.side - 2 * ring.width).toBe((2 * ring.inner) / ring.cellSize);
    }
    expect(rings[rings.length - 1].outer).toBeGreaterThan(250_000);
  });

  it('join the grid and each other without a crack, an overlap or a flipped triangle', { timeout: 60_000 }, () => {
    // 14 k grid triangles and 33 k ring triangles, all in whole metres: exact arithmetic.
    expect(tilingProblems(drawnSea(rings), rings[rings.length - 1].outer)).toEqual([]);
  });

  it('finds the crack when the grid border does not snap to the first ring (the check can fail)', { timeout: 60_000 }, () => {
    expect(tilingProblems(drawnSea(rings, true), rings[rings.length - 1].outer).some((p) => p.startsWith('open edge'))).toBe(true);
  });

  it("finds the T-junction at a cell's corner with the usual diagonal there (the check can fail)", () => {
    const ring = rings[0];
    const plain = squareGrid(RING_OWN_STEP, RING_CELL_QUADS);
    const triangles: Point[][] = [];
    const cellAt = (grid: typeof plain, x0: number, z0: number, steps: number[]) => {
      for (let t = 0; t < grid.indices.length; t += 3) {
        triangles.push(
          [0, 1, 2].map((c) => {
            const v = grid.indices[t + c] * 3;
            const [si, sj] = snapGridVertex(grid.positions[v], grid.positions[v + 2], CHUNK_QUADS, steps);
            return [x0 + si, z0 + sj] as Point;
          }),
        );
      }
    };
    // One corner cell with both outer sides snapped, alone: its outline is the cell's square.
    cellAt(plain, -CHUNK_QUADS / 2, -CHUNK_QUADS / 2, [2 * RING_OWN_STEP, RING_OWN_STEP, 2 * RING_OWN_STEP, RING_OWN_STEP]);
    expect(ring.width).toBe(1);
    expect(tilingProblems(triangles, CHUNK_QUADS / 2).length).toBeGreaterThan(0);
  });

  it("end where the skirt starts: its inner vertices are the last ring's outer corners, its quads face up", () => {
    const last = rings[rings.length - 1];
    const { points, indices } = skirtMesh(last);
    const corners = new Set<string>();
    for (let k = 0; k <= last.side; k++) {
      const t = -last.outer + k * last.cellSize;
      for (const p of [
        [t, -last.outer],
        [t, last.outer],
        [-last.outer, t],
        [last.outer, t],
      ])
        corners.add(`${p}`);
    }
    const inner = new Set<string>();
    for (let v = 0; v < points.length / 2; v += 2) inner.add(`${points[v * 2]},${points[v * 2 + 1]}`);
    expect(inner).toEqual(corners);
    for (let t = 0; t < indices.length; t += 3) {
      const [a, b, c] = [0, 1, 2].map((k) => [points[indices[t + k] * 2], points[indices[t + k] * 2 + 1]]);
      expect((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).toBeLessThan(0);
    }
  });

  // margin: a wave model's sideways displacement, which grows the boxes of rings 1 and 2 (still waving) in x and z.
  for (const [seed, margin] of [
    [3, 0],
    [8, 0],
    [5, 60],
  ]) {
    it(`cull with each ring's quadtree exactly the cells a test of every cell keeps (seed ${seed}, margin ${margin} m)`, () => {
      const random = seededRandom(seed);
      const selector = new FarRingSelector(HALF);
      let grown = 0;
      for (let n = 0; n < 40; n++) {
        const eye: [number, number, number] = [(random() - 0.5) * 2000, 0.5 + random() ** 2 * 10_000, (random() - 0.5) * 2000];
        const yaw = random() * 2 * Math.PI;
        const pitch = (-89 + random() * 120) * (Math.PI / 180);
        const target: [number, number, number] = [
          eye[0] + Math.cos(pitch) * Math.cos(yaw),
          eye[1] + Math.sin(pitch),
          eye[2] + Math.cos(pitch) * Math.sin(yaw),
        ];
        const planes = planesFromMatrix(viewProjection(eye, target, 55, 16 / 9, 0.5, 1e9));
        const [cx, cz] = [Math.round(eye[0] / 48) * 48, Math.round(eye[2] / 48) * 48];
        const withoutMargin = selector.select(planes, cx, cz, -2.3, 2.3);
        const count = selector.select(planes, cx, cz, -2.3, 2.3, margin);
        if (count > withoutMargin) grown++;
        const chosen = new Set<string>();
        for (let k = 0; k < count; k++) chosen.add(`${selector.ringOf[k]}:${selector.cellI[k]},${selector.cellJ[k]}`);
        const expected = new Set<string>();
        selector.rings.forEach((ring, r) => {
          for (let j = 0; j < ring.side; j++) {
            for (let i = 0; i < ring.side; i++) {
              if (!inRingHole(ring, i, j) && !ringCellOutside(planes, ring, i, j, cx, cz, -2.3, 2.3, margin))
                expected.add(`${r}:${i},${j}`);
            }
          }
        });
        expect(chosen).toEqual(expected);
      }
      // The margin must matter somewhere, or this would not test it.
      if (margin > 0) expect(grown).toBeGreaterThan(0);
    });
  }

  it('flatten the waves only past the grid: the fade ends where ring 3 begins', () => {
    expect(FAR_FADE_END).toBe(rings[1].outer);
  });
});
