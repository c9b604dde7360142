import { describe, expect, it } from 'vitest';
import { Frustum, Matrix4, PerspectiveCamera } from 'three';
import { viewProjection } from '../../../support/cameraMath';
import { ChunkQuadtree } from '../../../../src/sim/lod/chunkQuadtree';
import { chunkGrid } from '../../../../src/sim/lod/chunkGrid';
import { ChunkSelector, OCEAN_CHUNKS_PER_SIDE, OCEAN_EXTENT, oceanOrigin } from '../../../../src/sim/lod/chunkSelection';
import { snapEdgeCoordinate, snapGridVertex, snappedEdge } from '../../../../src/sim/lod/edgeSnap';
import { classifyBox, distanceToBox, OUTSIDE, planesFromMatrix, pointInside, type Plane } from '../../../../src/sim/lod/frustumMath';
import { seededRandom } from '../../../../src/sim/noise/integerHash';
import {
  BAND_STEPS,
  bandForDistance,
  bandQuads,
  bandStart,
  CHUNK_QUADS,
  CHUNK_SIZE,
  MAX_LOD_BANDS,
} from '../../../../src/sim/lod/lodBands';

const BOUNDS_HEIGHT = 2.3;

interface RandomView {
  camera: [number, number, number];
  target: [number, number, number];
  fov: number;
  aspect: number;
  near: number;
  far: number;
}

/** Cameras anywhere over the sea, low or high, looking any way from straight down to up. */
function randomView(random: () => number): RandomView {
  const camera: [number, number, number] = [(random() - 0.5) * 3000, 0.3 + random() ** 3 * 800, (random() - 0.5) * 3000];
  const yaw = random() * 2 * Math.PI;
  const pitch = (-89 + random() * 150) * (Math.PI / 180);
  const target: [number, number, number] = [
    camera[0] + Math.cos(pitch) * Math.cos(yaw),
    camera[1] + Math.sin(pitch),
    camera[2] + Math.cos(pitch) * Math.sin(yaw),
  ];
  return {
    camera,
    target,
    fov: 20 + random() * 80,
    aspect: 0.4 + random() * 2.4,
    near: 0.1 + random(),
    far: random() < 0.3 ? 100 + random() * 2000 : 20000,
  };
}

function planesOf(view: RandomView): Plane[] {
  return planesFromMatrix(viewProjection(view.camera, view.target, view.fov, view.aspect, view.near, view.far));
}

function bruteForceLeaves(planes: Plane[], originX: number, originZ: number): number[] {
  const leaves: number[] = [];
  for (let j = 0; j < OCEAN_CHUNKS_PER_SIDE; j++) {
    for (let i = 0; i < OCEAN_CHUNKS_PER_SIDE; i++) {
      const x0 = originX + i * CHUNK_SIZE;
      const z0 = originZ + j * CHUNK_SIZE;
      if (classifyBox(planes, x0, -BOUNDS_HEIGHT, z0, x0 + CHUNK_SIZE, BOUNDS_HEIGHT, z0 + CHUNK_SIZE) !== OUTSIDE)
        leaves.push(j * OCEAN_CHUNKS_PER_SIDE + i);
    }
  }
  return leaves;
}

describe('frustum planes', () => {
  it('match three.js Frustum for the same camera (seed 5)', () => {
    const random = seededRandom(5);
    for (let n = 0; n < 20; n++) {
      const view = randomView(random);
      const camera = new PerspectiveCamera(view.fov, view.aspect, view.near, view.far);
      camera.position.fromArray(view.camera);
      camera.lookAt(...view.target);
      camera.updateMatrixWorld();
      const frustum = new Frustum().setFromProjectionMatrix(
        new Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse),
      );
      const ours = planesOf(view);
      frustum.planes.forEach((plane, k) => {
        expect(ours[k].nx).toBeCloseTo(plane.normal.x, 5);
        expect(ours[k].ny).toBeCloseTo(plane.normal.y, 5);
        expect(ours[k].nz).toBeCloseTo(plane.normal.z, 5);
        expect(ours[k].d / Math.max(1, Math.abs(plane.constant))).toBeCloseTo(plane.constant / Math.max(1, Math.abs(plane.constant)), 5);
      });
    }
  });
});

describe('quadtree culling', () => {
  for (const seed of [1, 2, 3, 4, 5, 6, 7, 8]) {
    it(`selects exactly the leaves a brute-force test of every leaf keeps (seed ${seed})`, () => {
      const random = seededRandom(seed);
      const tree = new ChunkQuadtree(OCEAN_CHUNKS_PER_SIDE);
      const out = new Uint32Array(tree.leafCount);
      for (let n = 0; n < 25; n++) {
        const view = randomView(random);
        const planes = planesOf(view);
        const [ox, oz] = oceanOrigin(view.camera[0], view.camera[2]);
        const count = tree.select(planes, ox, oz, CHUNK_SIZE, -BOUNDS_HEIGHT, BOUNDS_HEIGHT, out);
        const selected = Array.from(out.subarray(0, count)).sort((a, b) => a - b);
        expect(new Set(selected).size).toBe(count);
        expect(selected).toEqual(bruteForceLeaves(planes, ox, oz));
      }
    });

    it(`misses no chunk with a visible point of the wave band (seed ${seed})`, () => {
      const random = seededRandom(100 + seed);
      const tree = new ChunkQuadtree(OCEAN_CHUNKS_PER_SIDE);
      const out = new Uint32Array(tree.leafCount);
      let visiblePoints = 0;
      for (let n = 0; n < 10; n++) {
        const view = randomView(random);
        const planes = planesOf(view);
        const [ox, oz] = oceanOrigin(view.camera[0], view.camera[2]);
        const selected = new Set(out.subarray(0, tree.select(planes, ox, oz, CHUNK_SIZE, -BOUNDS_HEIGHT, BOUNDS_HEIGHT, out)));
        for (let p = 0; p < 3000; p++) {
          const x = ox + random() * OCEAN_EXTENT;
          const z = oz + random() * OCEAN_EXTENT;
          const y = (random() * 2 - 1) * BOUNDS_HEIGHT;
          if (!pointInside(planes, x, y, z)) continue;
          visiblePoints++;
          const leaf = Math.floor((z - oz) / CHUNK_SIZE) * OCEAN_CHUNKS_PER_SIDE + Math.floor((x - ox) / CHUNK_SIZE);
          expect(selected.has(leaf)).toBe(true);
        }
      }
      // The cameras must actually see some sea for this to test anything.
      expect(visiblePoints).toBeGreaterThan(100);
    });
  }

  it('keeps nothing when the camera looks straight up from above the waves', () => {
    const tree = new ChunkQuadtree(OCEAN_CHUNKS_PER_SIDE);
    const out = new Uint32Array(tree.leafCount);
    const planes = planesFromMatrix(viewProjection([0, 10, 0], [0, 100, 0], 55, 16 / 9, 0.5, 20000));
    const [ox, oz] = oceanOrigin(0, 0);
    expect(tree.select(planes, ox, oz, CHUNK_SIZE, -BOUNDS_HEIGHT, BOUNDS_HEIGHT, out)).toBe(0);
  });

  it('works on grids that are not powers of two, down to one chunk', () => {
    for (const side of [1, 2, 3, 5, 7, 84]) {
      const tree = new ChunkQuadtree(side);
      const out = new Uint32Array(tree.leafCount);
      // A frustum wide enough to hold everything: every leaf comes back once.
      const planes = planesFromMatrix(viewProjection([0, 5000, 0], [0, 0, 0.001], 120, 1, 1, 20000));
      const count = tree.select(planes, -side * 24, -side * 24, CHUNK_SIZE, -1, 1, out);
      expect(Array.from(out.subarray(0, count)).sort((a, b) => a - b)).toEqual(Array.from({ length: side * side }, (_, k) => k));
    }
  });
});

describe('LOD bands', () => {
  it('follow the seed: full within L, every 2nd vertex to 2L, every 3rd beyond', () => {
    expect(BAND_STEPS.slice(0, 3)).toEqual([1, 2, 3]);
    expect(bandForDistance(0, 100, 3)).toBe(0);
    expect(bandForDistance(99.9, 100, 3)).toBe(0);
    expect(bandForDistance(100, 100, 3)).toBe(1);
    expect(bandForDistance(199.9, 100, 3)).toBe(1);
    expect(bandForDistance(200, 100, 3)).toBe(2);
    expect(bandForDistance(1e6, 100, 3)).toBe(2);
  });

  it('double start and step past the third band, and stop at the band count', () => {
    expect([0, 1, 2, 3, 4, 5].map((b) => bandStart(b, 50))).toEqual([0, 50, 100, 200, 400, 800]);
    expect(bandForDistance(399, 50, 6)).toBe(3);
    expect(bandForDistance(400, 50, 6)).toBe(4);
    expect(bandForDistance(1e6, 50, 6)).toBe(5);
    expect(bandForDistance(1e6, 50, 1)).toBe(0);
    expect(bandForDistance(150, 50, 2)).toBe(1);
    for (const step of BAND_STEPS) expect(CHUNK_QUADS % step).toBe(0);
    expect(MAX_LOD_BANDS).toBe(BAND_STEPS.length);
  });

  for (const seed of [21, 22, 23]) {
    // When L ≥ a chunk.
    it(`give each chunk its nearest point's band, neighbours at most one band apart (seed ${seed})`, () => {
      const random = seededRandom(seed);
      const selector = new ChunkSelector();
      for (let n = 0; n < 20; n++) {
        const view = randomView(random);
        const lodDistance = CHUNK_SIZE + random() * 300;
        const [originX, originZ] = oceanOrigin(view.camera[0], view.camera[2]);
        const input = {
          planes: planesOf(view),
          camera: view.camera,
          originX,
          originZ,
          maxDisplacement: BOUNDS_HEIGHT,
          lodDistance,
          lodBands: 6,
        };
        const count = selector.select(input);
        expect(selector.lodCounts.reduce((a, b) => a + b, 0)).toBe(count);
        // Collected rather than asserted one by one: thousands of expect() calls are slow.
        const wrong: string[] = [];
        for (let k = 0; k < count; k++) {
          const leaf = selector.leaves[k];
          const i = leaf % OCEAN_CHUNKS_PER_SIDE;
          const j = Math.floor(leaf / OCEAN_CHUNKS_PER_SIDE);
          const x0 = originX + i * CHUNK_SIZE;
          const z0 = originZ + j * CHUNK_SIZE;
          const d = distanceToBox(...view.camera, x0, -BOUNDS_HEIGHT, z0, x0 + CHUNK_SIZE, BOUNDS_HEIGHT, z0 + CHUNK_SIZE);
          const band = selector.bands[k];
          if (band !== bandForDistance(d, lodDistance, 6)) wrong.push(`chunk ${i},${j} at ${d} m has band ${band}`);
          const neighbours: [number, number][] = [
            [i - 1, j],
            [i + 1, j],
            [i, j - 1],
            [i, j + 1],
          ];
          neighbours.forEach(([ni, nj], side) => {
            const inside = ni >= 0 && nj >= 0 && ni < OCEAN_CHUNKS_PER_SIDE && nj < OCEAN_CHUNKS_PER_SIDE;
            let other = band;
            if (inside) {
              const nx = originX + ni * CHUNK_SIZE;
              const nz = originZ + nj * CHUNK_SIZE;
              other = bandForDistance(
                distanceToBox(...view.camera, nx, -BOUNDS_HEIGHT, nz, nx + CHUNK_SIZE, BOUNDS_HEIGHT, nz + CHUNK_SIZE),
                lodDistance,
                6,
              );
            }
            if (Math.abs(other - band) > 1) wrong.push(`chunk ${i},${j} band ${band} next to band ${other}`);
            // On the grid's border the neighbour is the first far ring, one vertex per chunk corner.
            const expected = inside ? Math.max(BAND_STEPS[band], BAND_STEPS[other]) : CHUNK_QUADS;
            if (selector.edgeSteps[k * 4 + side] !== expected)
              wrong.push(`chunk ${i},${j} side ${side}: step ${selector.edgeSteps[k * 4 + side]}, expected ${expected}`);
          });
        }
        expect(wrong).toEqual([]);
      }
    });
  }
});

/**
 * Two chunks side by side as the GPU draws them (grid units, edge vertices snapped),
 * degenerate triangles dropped. Returns every triangle as three [x, z] corners.
 */
function drawnPair(bandA: number, bandB: number, alongX: boolean): [number, number][][] {
  const shared = Math.max(BAND_STEPS[bandA], BAND_STEPS[bandB]);
  const triangles: [number, number][][] = [];
  const place = (band: number, edgeSteps: number[], dx: number, dz: number) => {
    const { positions, indices } = chunkGrid(band);
    for (let t = 0; t < indices.length; t += 3) {
      const corners = [0, 1, 2].map((c) => {
        const v = indices[t + c] * 3;
        const [si, sj] = snapGridVertex(positions[v], positions[v + 2], CHUNK_QUADS, edgeSteps);
        return [si + dx, sj + dz] as [number, number];
      });
      const [a, b, c] = corners;
      const area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if (area !== 0) triangles.push(corners);
    }
  };
  const own = (band: number): number[] => [1, 2, 3, 4].map(() => BAND_STEPS[band]);
  const a = own(bandA);
  const b = own(bandB);
  if (alongX) {
    a[1] = shared;
    b[0] = shared;
    place(bandA, a, 0, 0);
    place(bandB, b, CHUNK_QUADS, 0);
  } else {
    a[3] = shared;
    b[2] = shared;
    place(bandA, a, 0, 0);
    place(bandB, b, 0, CHUNK_QUADS);
  }
  return triangles;
}

describe('edges between bands', () => {
  it('snap a fine edge onto exactly the coarse edge vertices for every pair of bands', () => {
    for (let fine = 0; fine < MAX_LOD_BANDS; fine++) {
      for (let coarse = fine; coarse < MAX_LOD_BANDS; coarse++) {
        const expected = Array.from({ length: bandQuads(coarse) + 1 }, (_, k) => k * BAND_STEPS[coarse]);
        expect(snappedEdge(CHUNK_QUADS, BAND_STEPS[fine], BAND_STEPS[coarse])).toEqual(expected);
      }
    }
    expect(snapEdgeCoordinate(4, 3)).toBe(3);
    expect(snapEdgeCoordinate(2, 3)).toBe(3);
    expect(snapEdgeCoordinate(1, 3)).toBe(0);
  });

  for (const alongX of [true, false]) {
    it(`make a watertight, unflipped seam between every pair of bands (neighbour along ${alongX ? 'x' : 'z'})`, () => {
      const problems: string[] = [];
      for (let bandA = 0; bandA < MAX_LOD_BANDS; bandA++) {
        for (let bandB = 0; bandB < MAX_LOD_BANDS; bandB++) {
          const triangles = drawnPair(bandA, bandB, alongX);
          const width = alongX ? 2 * CHUNK_QUADS : CHUNK_QUADS;
          const depth = alongX ? CHUNK_QUADS : 2 * CHUNK_QUADS;
          const directed = new Map<string, number>();
          let area = 0;
          let flipped = 0;
          for (const [a, b, c] of triangles) {
            const signed = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            area += Math.abs(signed) / 2;
            if (signed > 0) flipped++;
            for (const [p, q] of [
              [a, b],
              [b, c],
              [c, a],
            ]) {
              const key = `${p}|${q}`;
              directed.set(key, (directed.get(key) ?? 0) + 1);
            }
          }
          if (flipped > 0) problems.push(`bands ${bandA}/${bandB}: ${flipped} flipped triangles`);
          // No overlap and no hole: the triangles tile the two chunks' rectangle exactly.
          if (area !== width * depth) problems.push(`bands ${bandA}/${bandB}: area ${area}, expected ${width * depth}`);
          // Every edge inside the rectangle is walked once each way; only the outline is open.
          for (const [key, count] of directed) {
            if (count !== 1) problems.push(`bands ${bandA}/${bandB}: edge ${key} walked ${count} times`);
            const [p, q] = key.split('|').map((s) => s.split(',').map(Number));
            if (directed.has(`${q}|${p}`)) continue;
            const onOutline = (p[0] === q[0] && (p[0] === 0 || p[0] === width)) || (p[1] === q[1] && (p[1] === 0 || p[1] === depth));
            if (!onOutline) problems.push(`bands ${bandA}/${bandB}: open edge ${key}`);
          }
        }
      }
      expect(problems).toEqual([]);
    });
  }
});
