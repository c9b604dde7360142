// Windrows: in a strong wind the foam left behind lies in streaks along it, where Langmuir
// circulation sweeps what floats (the GLSL twin of windrowShare in src/sim/waves/fft/windrows.ts;
// read the physics there). Where the foam lies is no longer where its wave group broke but where
// the windrows gather it: value noise on a lattice laid along the wind, its cells
// WINDROW_STRETCH times longer along it than across, carried with the surface's drift, of the
// same mean share, so the foam is moved, not made. Compiled in (OCEAN_WINDROWS) only in a wind
// strong enough for it (Beaufort 7) with the windrows parameter on.
#include <oceano_constants>
uniform vec4 uWindrowAxes;     // lattice coordinates per metre: u = dot(xy, r) along the wind, v = dot(zw, r) across
uniform ivec2 uWindrowCells;   // whole cells where the render origin falls on the lattice
uniform vec2 uWindrowOffset;   // and the rest, in cells
uniform int uWindrowSeed;      // the user's seed mixed with the windrows' stream
uniform float uWindrowStrength;  // 0 up to Beaufort 7, 1 from Beaufort 9

// The share of the foam left behind that lies at p, given the share its group would let lie.
// Where a pixel spans more than a quarter of a cell across, the streaks would alias into
// flicker far away: they hand back to the groups, fully at half a cell.
#ifdef OCEAN_WINDROWS
float foamWindrowShare(vec2 p, bool near, float groupShare) {
  vec2 r = near ? p : p - uFoamBreakupOrigin;
  vec2 u = vec2(dot(uWindrowAxes.xy, r), dot(uWindrowAxes.zw, r)) + uWindrowOffset;
  float gathered = smoothstep(WINDROW_GATHER_FROM, WINDROW_GATHER_TO, foamValueNoise(u, uWindrowCells, uWindrowSeed));
#ifdef WAVE_FRAGMENT_STAGE
  float footprint = max(length(dFdx(p)), length(dFdy(p)));
  float resolved = 1.0 - smoothstep(0.25 * WINDROW_SPACING, 0.5 * WINDROW_SPACING, footprint);
#else
  const float resolved = 1.0;
#endif
  return mix(groupShare, FOAM_GROUP_SHARE_MEAN * gathered / WINDROW_GATHER_MEAN, uWindrowStrength * resolved);
}
#else
float foamWindrowShare(vec2 p, bool near, float groupShare) {
  return groupShare;
}
#endif
