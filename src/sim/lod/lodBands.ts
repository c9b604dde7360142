/**
 * The seed's distance bands ("Optimización: LOD"): every vertex within L of the camera,
 * every 2nd from L to 2L, every 3rd beyond. The ocean is cut into square chunks of
 * CHUNK_QUADS × CHUNK_QUADS full-resolution quads; a chunk's band sets its vertex step.
 *
 * Beyond the seed's three bands, each further band doubles both where it starts and its
 * vertex step (band 3: every 6th vertex from 4L, band 4: every 12th from 8L, band 5: every
 * 24th from 16L). The step then grows in proportion to the distance, which keeps the
 * triangles' size on screen roughly constant, and every step divides CHUNK_QUADS, which the
 * crack-free edges need (see edgeSnap.ts). The last band enabled reaches to the horizon.
 */

/** Full-resolution vertex spacing, metres. */
export const BASE_STEP = 2;
/** Full-resolution quads along a chunk's side: divisible by every band's step. */
export const CHUNK_QUADS = 24;
export const CHUNK_SIZE = BASE_STEP * CHUNK_QUADS;
/** The LOD debugger's tint for each band, near to far (linear RGB); the shader reads these as LOD_BAND_COLORS. */
export const LOD_BAND_COLORS: readonly (readonly [number, number, number])[] = [
  [0.95, 0.2, 0.15],
  [0.95, 0.6, 0.1],
  [0.9, 0.9, 0.15],
  [0.2, 0.8, 0.25],
  [0.15, 0.75, 0.9],
  [0.5, 0.3, 0.95],
];
/** Vertex step of each band, in full-resolution quads. */
export const BAND_STEPS = [1, 2, 3, 6, 12, 24] as const;
export const MAX_LOD_BANDS = BAND_STEPS.length;

export function bandStep(band: number): number {
  return BAND_STEPS[band];
}

/** Distance from the camera where a band begins, metres: 0, L, 2L, 4L, 8L, … */
export function bandStart(band: number, lodDistance: number): number {
  return band === 0 ? 0 : lodDistance * 2 ** (band - 1);
}

/** The band of a chunk whose nearest point is `distance` metres from the camera. */
export function bandForDistance(distance: number, lodDistance: number, bands: number): number {
  let band = 0;
  while (band + 1 < bands && distance >= bandStart(band + 1, lodDistance)) band++;
  return band;
}

/** Quads along a chunk's side at a band, and the triangles of one chunk. */
export function bandQuads(band: number): number {
  return CHUNK_QUADS / BAND_STEPS[band];
}

/**
 * Vertex spacing, metres, up to which a band's vertex normals keep its waves: ocean.frag fades
 * per-pixel detail normals in from here (smoothstep from DETAIL_NORMALS_FROM, so exactly 0 at
 * or below it). The bands at or below it are drawn without that code (OceanMaterial.near).
 */
export const DETAIL_NORMALS_FROM = 8;

/** Whether a grid band's vertices lie far enough apart for ocean.frag's detail normals. */
export function bandHasDetailNormals(band: number): boolean {
  return BAND_STEPS[band] * BASE_STEP > DETAIL_NORMALS_FROM;
}

export function bandTriangles(band: number): number {
  return 2 * bandQuads(band) ** 2;
}

/**
 * The most times the nearest band's quads may be split per side: vertices 0.5 m apart. A sea
 * whose short waves are steep enough to show the trochoid's cusp asks for it
 * (WaveModelView.finestVertexStep): with 2 m between vertices a 4 m crest is drawn from two
 * vertices, and the per-pixel normal's back slopes show on the coarse triangles as pale
 * shelves (docs/light-tiling-and-crests.md, "Gerstner's terraces").
 */
export const MAX_REFINEMENT = 4;

/** How many times per side the nearest band's quads are split for vertices at most `step` metres apart: 1, 2 or 4. */
export function nearBandRefinement(step: number): number {
  let refine = 1;
  while (refine < MAX_REFINEMENT && BASE_STEP / refine > step) refine *= 2;
  return refine;
}

/**
 * An edge step shared with a neighbour (in full-resolution quads) in a refined chunk's own
 * units: between two refined chunks every refined vertex is shared (1); toward a coarser
 * band its vertices snap onto the neighbour's, `refine` times as many units apart.
 */
export function refinedEdgeStep(edgeStep: number, refine: number): number {
  return edgeStep > BAND_STEPS[0] ? edgeStep * refine : 1;
}
