import { snapEdgeCoordinate } from './edgeSnap';
import { BAND_STEPS, bandStart, CHUNK_SIZE, MAX_LOD_BANDS } from './lodBands';

/**
 * Geomorphing between LOD bands, as in CDLOD (Strugar, "Continuous Distance-Dependent Level
 * of Detail for Rendering Heightmaps", JGT 2009): over a zone just before the distance where
 * a chunk passes to the next band, each of its vertices slides in the plane towards where the
 * coarser band's grid puts it (the same snap the crack-free edges use, src/sim/lod/edgeSnap.ts).
 * At the zone's end the fine grid lies exactly on the coarse one (its other triangles are
 * degenerate), so the switch of band changes nothing on screen. The surface function is not
 * touched: only which points of it the grid samples.
 *
 * The morph factor of a vertex depends only on its own (unmorphed) place, never on its
 * chunk, so chunks sharing a vertex agree on it. Its distance is measured as the bands
 * measure chunks (src/sim/lod/chunkSelection.ts): to the vertical segment y ∈ [−h, h] above it.
 *
 * Two guarantees keep the seams closed, and fix how wide a zone may be:
 * - a chunk's vertices lie at most CHUNK_REACH farther than its nearest point, so on a side
 *   shared with a coarser neighbour (whose nearest point is past the band start) every
 *   vertex is already fully morphed: it sits where the neighbour's vertex is;
 * - a coarser chunk's vertices on a side shared with a finer neighbour lie less than
 *   CHUNK_REACH past its own band start: its zone must begin after that, so they have not
 *   started to move. This also means no vertex ever needs to morph two bands at once.
 * Where L is so short that no zone fits (L < about 70 m), that band change keeps its pop.
 *
 * shaders/ocean.vert does the same in GLSL; keep the two in step.
 */

/** Widest a chunk's vertices can be from its nearest point in the plane, metres. */
export const CHUNK_REACH = CHUNK_SIZE * Math.SQRT2;
/** Slack for float32 in the shader: zones end this far before the band start, metres. */
export const MORPH_SAFETY = 1;
/** A zone spans at most this fraction of the band it ends. */
export const MORPH_FRACTION = 0.5;

export interface MorphZone {
  /** Distance where the vertices of `band` start to move, metres (Infinity: never). */
  start: number;
  /** 1 / the zone's width, 1/m (0 where there is no zone). */
  inverseWidth: number;
}

/** The zone over which vertices of `band` morph towards band + 1, with `bands` in use. */
export function morphZone(band: number, lodDistance: number, bands: number): MorphZone {
  if (band + 1 >= bands || band + 1 >= MAX_LOD_BANDS) return { start: Infinity, inverseWidth: 0 };
  const end = bandStart(band + 1, lodDistance) - MORPH_SAFETY;
  const from = bandStart(band, lodDistance);
  // The band's own first CHUNK_REACH (plus slack) must stay unmorphed, except in band 0 which has no finer neighbour.
  const earliest = band === 0 ? from : from + CHUNK_REACH + MORPH_SAFETY;
  const width = Math.min(MORPH_FRACTION * (end + MORPH_SAFETY - from), end - earliest);
  if (width <= 0) return { start: Infinity, inverseWidth: 0 };
  return { start: end - width, inverseWidth: 1 / width };
}

/** Every band's zone, as the shader's uniforms hold them: (start, 1/width) per band. */
export function morphZones(lodDistance: number, bands: number, enabled = true, out = new Float32Array(MAX_LOD_BANDS * 2)): Float32Array {
  for (let band = 0; band < MAX_LOD_BANDS; band++) {
    const zone = enabled ? morphZone(band, lodDistance, bands) : { start: Infinity, inverseWidth: 0 };
    // float32 has no room for Infinity in a uniform on every driver: a distance no camera reaches.
    out[band * 2] = Number.isFinite(zone.start) ? zone.start : 1e30;
    out[band * 2 + 1] = zone.inverseWidth;
  }
  return out;
}

/** Morph factor in [0, 1] of a vertex `distance` metres away, in a chunk of `band`. */
export function morphFactor(distance: number, zones: Float32Array, band: number): number {
  if (band >= MAX_LOD_BANDS) return 0;
  const t = (distance - zones[band * 2]) * zones[band * 2 + 1];
  return t <= 0 ? 0 : t >= 1 ? 1 : t;
}

/** Distance from `camera` to the segment x, y ∈ [−h, h], z: how the bands measure it. */
export function morphDistance(x: number, z: number, camera: readonly [number, number, number], h: number): number {
  const dy = camera[1] > h ? camera[1] - h : camera[1] < -h ? -h - camera[1] : 0;
  return Math.hypot(x - camera[0], dy, z - camera[2]);
}

/** A grid coordinate `k` (full-resolution quads) slid by `factor` towards the coarser band's vertex. */
export function morphCoordinate(k: number, band: number, factor: number): number {
  if (band + 1 >= MAX_LOD_BANDS || factor === 0) return k;
  return k + factor * (snapEdgeCoordinate(k, BAND_STEPS[band + 1]) - k);
}

export interface ChunkPlacement {
  /** World x, z of the chunk's corner, metres. */
  cornerX: number;
  cornerZ: number;
  band: number;
  /** Metres per grid unit. */
  unit: number;
  /** Full-resolution quads along a side. */
  quads: number;
  /** Steps shared with the neighbours on sides −x, +x, −z, +z. */
  edgeSteps: readonly number[];
}

/**
 * World x, z where the vertex shader puts grid vertex (i, j) of a chunk (the twin of
 * shaders/ocean.vert): morphed by its distance from the LOD's camera, then, on a side shared
 * with a coarser neighbour, snapped onto the neighbour's vertex as before (there the morph
 * is already complete when the neighbour is one band coarser).
 */
export function morphedVertex(
  i: number,
  j: number,
  chunk: ChunkPlacement,
  camera: readonly [number, number, number],
  h: number,
  zones: Float32Array,
): [number, number] {
  const x = chunk.cornerX + i * chunk.unit;
  const z = chunk.cornerZ + j * chunk.unit;
  const factor = morphFactor(morphDistance(x, z, camera, h), zones, chunk.band);
  let si = morphCoordinate(i, chunk.band, factor);
  let sj = morphCoordinate(j, chunk.band, factor);
  // The far rings (band ≥ MAX_LOD_BANDS) never morph and always snap their sides, as before.
  const own = chunk.band < MAX_LOD_BANDS ? BAND_STEPS[chunk.band] : 0;
  const [sx0, sx1, sz0, sz1] = chunk.edgeSteps;
  if (i === 0 && sx0 > own) sj = snapEdgeCoordinate(j, sx0);
  else if (i === chunk.quads && sx1 > own) sj = snapEdgeCoordinate(j, sx1);
  if (j === 0 && sz0 > own) si = snapEdgeCoordinate(i, sz0);
  else if (j === chunk.quads && sz1 > own) si = snapEdgeCoordinate(i, sz1);
  return [chunk.cornerX + si * chunk.unit, chunk.cornerZ + sj * chunk.unit];
}
