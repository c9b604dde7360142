// The field that breaks the whitecaps' repeat (the GLSL twin of breakupNoise in
// src/sim/waves/fft/foamBreakup.ts, read the why there): value noise whose lattice values come
// from the seed's integer hash (src/sim/noise/integerHash.ts, MurmurHash3's finaliser), which
// does not repeat within 2³² cells. Cells an eighth of the peak wavelength wide, carried
// downwind at the group velocity. Where the render origin falls on each octave's lattice
// arrives split in double precision into whole cells and the rest (breakupLattice).
#include <oceano_constants>
uniform float uFoamBreakupScale;        // 1 / cell, 1/m
uniform ivec4 uFoamBreakupCells;        // whole cells of the render origin: first octave (xy), second (zw)
uniform vec4 uFoamBreakupOffset;        // the rest, in cells: first octave (xy), second (zw)
uniform vec2 uFoamBreakupOrigin;        // the render origin, m (for an absolute point only)
uniform int uFoamBreakupSeed;           // the user's seed mixed with the field's stream

// The seed's integer hash of a lattice cell, in [−1, 1) (integerNoise's twin).
float foamLatticeHash(ivec2 cell, int seed) {
  uint h = uint(cell.x) * 0x27d4eb2du ^ uint(cell.y) * 0x165667b1u ^ uint(seed) * 0x9e3779b1u;
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return float(h) / 2147483648.0 - 1.0;
}

// One octave of value noise at lattice coordinates `whole cells + u` (src/sim/noise/valueNoise.ts
// is the twin), in [−1, 1): the cells' hashes blended by the quintic fade. Also read by the
// windrows (shaders/foam/foamWindrows.glsl).
float foamValueNoise(vec2 u, ivec2 cells, int seed) {
  vec2 whole = floor(u);
  vec2 w = u - whole;
  w = w * w * w * (w * (w * 6.0 - 15.0) + 10.0);
  ivec2 cell = ivec2(whole) + cells;
  float a = foamLatticeHash(cell, seed);
  float b = foamLatticeHash(cell + ivec2(1, 0), seed);
  float c = foamLatticeHash(cell + ivec2(0, 1), seed);
  float d = foamLatticeHash(cell + ivec2(1, 1), seed);
  return mix(mix(a, b, w.x), mix(c, d, w.x), w.y);
}

#ifdef OCEAN_WAVE_GROUPS
// The field's two octaves at a grid point relative to the render origin (near) or absolute,
// each in [−1, 1): the second on a lattice turned by 30° and 2.31 times finer (BREAKUP_SECOND_OCTAVE).
vec2 foamBreakupOctaves(vec2 p, bool near) {
  vec2 u = (near ? p : p - uFoamBreakupOrigin) * uFoamBreakupScale;
  const mat2 TURN = mat2(0.8660254, 0.5, -0.5, 0.8660254) * 2.31;
  float first = foamValueNoise(u + uFoamBreakupOffset.xy, uFoamBreakupCells.xy, uFoamBreakupSeed);
  float second = foamValueNoise(TURN * u + uFoamBreakupOffset.zw, uFoamBreakupCells.zw, uFoamBreakupSeed);
  return vec2(first, second);
}

// The field from its two octaves, in [−1, 1).
float foamBreakupOfOctaves(vec2 octaves) {
  return (octaves.x + 0.5 * octaves.y) / 1.5;
}

float foamBreakup(vec2 p, bool near) {
  return foamBreakupOfOctaves(foamBreakupOctaves(p, near));
}

// A second field from the same octaves, uncorrelated with the first (their covariance,
// ½ var − ½ var, is zero): where the tiles' copies are blended (shaders/waves/fft.glsl), so
// that the foam, which gathers where the first is low, is not all on one copy.
float foamBreakupOther(vec2 octaves) {
  return (0.5 * octaves.x - octaves.y) / 1.5;
}

// The share of the foam left behind that lies where the group lets it: all of it in a group
// (the field below −0.6), none between groups (above 0.2); FOAM_GROUP_SHARE_MEAN on average
// (foamGroupShare in src/sim/waves/fft/foamBreakup.ts is the twin).
float foamGroupShare(float breakup) {
  return smoothstep(0.2, -0.6, breakup);
}
#else
// The waveGroups parameter off, for the lesson: no groups, so nothing shifts the breaking
// measure, and the foam left behind lies everywhere, at the share of it the groups let lie on
// average. The sea's threshold without the shift: ACTIVE_FOAM_SHARE_WITHOUT_GROUPS (fftWaveView.ts).
float foamBreakup(vec2 p, bool near) {
  return 0.0;
}

float foamGroupShare(float breakup) {
  return FOAM_GROUP_SHARE_MEAN;
}
#endif
