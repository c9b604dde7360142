/**
 * Crack-free edges between chunks of different bands, without T-junctions.
 *
 * Where a chunk meets a coarser neighbour, each of its edge vertices is moved along the edge
 * onto the neighbour's nearest edge vertex (integer grid units, so exact). Moving rather than
 * interpolating the height matters twice: the displacement is evaluated per vertex, so a
 * vertex left between two coarse ones would not lie on the coarse edge; and the seed's steps
 * 2 and 3 are not nested (a step-3 vertex at 3 is no step-2 vertex), so interpolation would
 * still cut corners. After the move every segment of the fine edge is either degenerate or
 * exactly one coarse segment, with bit-identical endpoints: watertight by construction.
 *
 * shaders/ocean.vert does the same with GLSL integers; keep the two in step.
 */
export function snapEdgeCoordinate(k: number, edgeStep: number): number {
  return Math.floor((k + Math.floor(edgeStep / 2)) / edgeStep) * edgeStep;
}

/**
 * The edge polyline a chunk of vertex step `ownStep` draws along one side `quads` grid units
 * long when that side's shared step is `edgeStep`: vertex coordinates after snapping, with
 * the repeats of degenerate segments removed.
 */
export function snappedEdge(quads: number, ownStep: number, edgeStep: number): number[] {
  const out: number[] = [];
  for (let k = 0; k <= quads; k += ownStep) {
    const s = snapEdgeCoordinate(k, edgeStep);
    if (out.length === 0 || out[out.length - 1] !== s) out.push(s);
  }
  return out;
}

/**
 * Where the vertex shader puts grid vertex (i, j) of a chunk `quads` long whose sides −x,
 * +x, −z, +z share the steps `edgeSteps` with their neighbours (the twin of shaders/ocean.vert).
 */
export function snapGridVertex(i: number, j: number, quads: number, edgeSteps: readonly number[]): [number, number] {
  let si = i;
  let sj = j;
  if (i === 0) sj = snapEdgeCoordinate(j, edgeSteps[0]);
  else if (i === quads) sj = snapEdgeCoordinate(j, edgeSteps[1]);
  if (j === 0) si = snapEdgeCoordinate(i, edgeSteps[2]);
  else if (j === quads) si = snapEdgeCoordinate(i, edgeSteps[3]);
  return [si, sj];
}
