import { describe, expect, it } from 'vitest';
import { chunkGrid } from '../../../../src/sim/lod/chunkGrid';
import { ChunkSelector, oceanOrigin } from '../../../../src/sim/lod/chunkSelection';
import type { Plane } from '../../../../src/sim/lod/frustumMath';
import { seededRandom } from '../../../../src/sim/noise/integerHash';
import { bandStart, CHUNK_QUADS, CHUNK_SIZE, BASE_STEP, MAX_LOD_BANDS } from '../../../../src/sim/lod/lodBands';
import { CHUNK_REACH, morphedVertex, morphZone, morphZones, type ChunkPlacement } from '../../../../src/sim/lod/lodMorph';
import { defaultParams } from '../../../../src/sim/params/params';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';

type Vec3 = [number, number, number];

/** Planes no box is outside of: every chunk is selected, so only the bands matter here. */
const EVERYWHERE: Plane[] = [{ nx: 0, ny: 1, nz: 0, d: 1e9 }];
const L = defaultParams().lodDistance;
const H = 2.3;

/** The chunks as the app selects them for a camera, and a way to place each one. */
function selectFor(camera: Vec3, selector: ChunkSelector, planes: Plane[] = EVERYWHERE) {
  const [originX, originZ] = oceanOrigin(camera[0], camera[2]);
  selector.select({ planes, camera, originX, originZ, maxDisplacement: H, lodDistance: L, lodBands: MAX_LOD_BANDS });
  const place = (i: number, j: number): ChunkPlacement | null => {
    const n = selector.leaves.subarray(0, selector.count).indexOf(j * selector.side + i);
    if (n < 0) return null;
    return {
      cornerX: originX + i * CHUNK_SIZE,
      cornerZ: originZ + j * CHUNK_SIZE,
      band: selector.bands[n],
      unit: BASE_STEP,
      quads: CHUNK_QUADS,
      edgeSteps: Array.from(selector.edgeSteps.subarray(n * 4, n * 4 + 4)),
    };
  };
  return { originX, originZ, place };
}

/**
 * The drawn surface's height at world (x, z): the chunk holding it, its vertices where
 * the vertex shader puts them (morphed, snapped), each at the wave's height there, and
 * the triangle that covers the point, interpolated as the rasteriser does.
 */
function drawnHeight(
  x: number,
  z: number,
  camera: Vec3,
  zones: Float32Array,
  selector: ChunkSelector,
  height: (x: number, z: number) => number,
): { height: number; band: number } {
  // Culled to a strip 200 m wide along the camera's path, which keeps the sweep fast.
  const strip: Plane[] = [
    { nx: 0, ny: 0, nz: 1, d: -(z - 100) },
    { nx: 0, ny: 0, nz: -1, d: z + 100 },
  ];
  const { originX, originZ, place } = selectFor(camera, selector, strip);
  const chunk = place(Math.floor((x - originX) / CHUNK_SIZE), Math.floor((z - originZ) / CHUNK_SIZE));
  if (!chunk) throw new Error('The point lies outside the chunk grid.');
  const { positions, indices } = GRIDS[chunk.band];
  const placed = new Float64Array((positions.length / 3) * 2);
  for (let v = 0; v < positions.length / 3; v++)
    placed.set(morphedVertex(positions[v * 3], positions[v * 3 + 2], chunk, camera, H, zones), v * 2);
  for (let t = 0; t < indices.length; t += 3) {
    const [ia, ib, ic] = [indices[t] * 2, indices[t + 1] * 2, indices[t + 2] * 2];
    const [ax, az, bx, bz, cx, cz] = [placed[ia], placed[ia + 1], placed[ib], placed[ib + 1], placed[ic], placed[ic + 1]];
    const area = (bx - ax) * (cz - az) - (bz - az) * (cx - ax);
    if (Math.abs(area) < 1e-9) continue;
    const wb = ((x - ax) * (cz - az) - (z - az) * (cx - ax)) / area;
    const wc = ((bx - ax) * (z - az) - (bz - az) * (x - ax)) / area;
    const wa = 1 - wb - wc;
    // Heights only for the covering triangle's corners: the wave is the costly part.
    if (wa >= -1e-9 && wb >= -1e-9 && wc >= -1e-9)
      return { height: wa * height(ax, az) + wb * height(bx, bz) + wc * height(cx, cz), band: chunk.band };
  }
  throw new Error(`No triangle covers (${x}, ${z}).`);
}

const GRIDS = Array.from({ length: MAX_LOD_BANDS }, (_, band) => chunkGrid(band));

/**
 * The camera flies away from fixed points along x, 0.5 m a step, from 20 m to 1.75 km:
 * every point's chunk passes through all six bands. Returns the largest change of the
 * drawn height between two steps, and how many band changes were crossed.
 */
function sweep(enabled: boolean): { worst: number; bandChanges: number } {
  const model = new SeedWaveModel(defaultParams());
  const height = (x: number, z: number) => model.displacement(x, z, 10)[1];
  const zones = morphZones(L, MAX_LOD_BANDS, enabled);
  const selector = new ChunkSelector();
  // Off every coarse lattice, at different places within a chunk (seed 13).
  const random = seededRandom(13);
  const points = Array.from({ length: 2 }, () => [5000 + random() * CHUNK_SIZE, 700 + random() * CHUNK_SIZE] as [number, number]);
  let worst = 0;
  let bandChanges = 0;
  for (const [px, pz] of points) {
    let previous: { height: number; band: number } | null = null;
    for (let d = 20; d <= 1750; d += 0.5) {
      const now = drawnHeight(px, pz, [px - d, 6, pz], zones, selector, height);
      if (previous) {
        worst = Math.max(worst, Math.abs(now.height - previous.height));
        if (now.band !== previous.band) bandChanges++;
      }
      previous = now;
    }
  }
  return { worst, bandChanges };
}

describe('geomorphing between LOD bands', () => {
  it('keeps the drawn surface continuous as the camera moves across every band boundary', () => {
    const morphing = sweep(true);
    // Every point crosses the five band boundaries.
    expect(morphing.bandChanges).toBe(2 * 5);
    // Measured 0.0049 m per 0.5 m step: the camera's own motion sliding vertices over the
    // waves (at most 2 m over the shortest, 31 m zone, times the slope); it shrinks with the
    // step, as a continuous function's does. The bound sits just above.
    expect(morphing.worst).toBeLessThan(0.006);
  }, 120_000);

  it('negative control: without morphing the same sweep jumps at the band changes', () => {
    const popping = sweep(false);
    // Measured 0.66 m: the fine grid's vertices vanish at once.
    expect(popping.worst).toBeGreaterThan(0.05);
  }, 120_000);

  it('leaves every seam watertight: chunks sharing a side put its vertices at the same places (seed 21)', () => {
    const random = seededRandom(21);
    const selector = new ChunkSelector();
    const zones = morphZones(L, MAX_LOD_BANDS);
    let sidesChecked = 0;
    for (let n = 0; n < 12; n++) {
      const camera: Vec3 = [(random() - 0.5) * 2000, 0.3 + random() ** 3 * 300, (random() - 0.5) * 2000];
      const { place } = selectFor(camera, selector);
      // The chunks around the camera out to 1 km, where every band change happens.
      const [oi, oj] = [42, 42];
      for (let j = oj - 21; j < oj + 21; j++) {
        for (let i = oi - 21; i < oi + 21; i++) {
          const a = place(i, j);
          const b = place(i + 1, j);
          if (!a || !b) continue;
          // Side +x of a is side −x of b: the sets of points each draws along it must match.
          const along = (chunk: ChunkPlacement, k: number) => {
            const pts = new Set<string>();
            const step = [1, 2, 3, 6, 12, 24][chunk.band];
            for (let q = 0; q <= CHUNK_QUADS; q += step) pts.add(morphedVertex(k, q, chunk, camera, H, zones).join(','));
            return [...pts].sort();
          };
          expect(along(a, CHUNK_QUADS)).toEqual(along(b, 0));
          if (a.band !== b.band) sidesChecked++;
        }
      }
    }
    expect(sidesChecked).toBeGreaterThan(30);
  }, 60_000);

  it('fits its zones where the seams stay closed, for every L the panel allows', () => {
    for (let lod = 10; lod <= 1000; lod += 5) {
      for (let band = 0; band + 1 < MAX_LOD_BANDS; band++) {
        const zone = morphZone(band, lod, MAX_LOD_BANDS);
        if (!Number.isFinite(zone.start)) {
          // Only a short L leaves a band change without a zone.
          expect(lod).toBeLessThan(75);
          continue;
        }
        const end = zone.start + 1 / zone.inverseWidth;
        expect(end).toBeLessThan(bandStart(band + 1, lod));
        if (band > 0) expect(zone.start).toBeGreaterThan(bandStart(band, lod) + CHUNK_REACH);
      }
      expect(morphZone(MAX_LOD_BANDS - 1, lod, MAX_LOD_BANDS).start).toBe(Infinity);
    }
  });
});
