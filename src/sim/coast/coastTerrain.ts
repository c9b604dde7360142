/**
 * Where the coast's ground bends, as distances seaward of the shoreline (metres; negative
 * inland): the bed is piecewise linear in that distance (seaDepth), so a mesh with vertices at
 * these distances and straight edges between them is exact across the profile. From `inland`
 * metres inland (the far edge of the land drawn), through the top of the slope (where the
 * ground reaches `landHeight`) and the shoreline, to `underwater` metres of depth (the part
 * of the bed seen through the shallows' surface, drawn with the land).
 */
export function terrainBreaks(slope: number, landHeight: number, inland: number, underwater: number): number[] {
  const top = -landHeight / slope;
  const breaks = [-inland, top, top / 2, 0, underwater / slope / 2, underwater / slope];
  return [...new Set(breaks.filter((s) => s >= -inland).sort((a, b) => a - b))];
}
