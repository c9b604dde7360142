// The sun's disc as the sky draws it (src/sim/optics/sunDisc.ts).
#ifndef OCEANO_SUN_DISC
#define OCEANO_SUN_DISC
#include <oceano_constants>

// Its soft edge, as the 8-bit sky cube holds it: how much of a pixel looking along `direction`
// it covers, from its edge (SUN_DISC_COS_EDGE) to its core (SUN_DISC_COS_CORE).
float sunDiscCoverage(vec3 direction, vec3 sun) {
  // No disc once the sun's centre is below the horizon.
  return smoothstep(SUN_DISC_COS_EDGE, SUN_DISC_COS_CORE, dot(direction, sun)) * step(0.0, sun.y);
}

// Its full brightness, which only the sky behind the scene draws (skyBackground.frag): within
// the middle of that edge, SUN_DISC_COS_MID, the disc of the same solid angle (a smoothstep
// averages one half over its ramp). The soft edge outside it is the cube's.
float insideSunDisc(vec3 direction, vec3 sun) {
  return step(SUN_DISC_COS_MID, dot(direction, sun)) * step(0.0, sun.y);
}

// How much of this pixel lies inside that disc, 0 to 1: how far the pixel's centre is inside
// its edge, measured in pixels (the cosine's change across one pixel), plus a half.
float sunDiscPixelShare(vec3 direction, vec3 sun) {
  float c = dot(direction, sun);
  return clamp((c - SUN_DISC_COS_MID) / max(fwidth(c), 1e-9) + 0.5, 0.0, 1.0) * step(0.0, sun.y);
}

#endif
