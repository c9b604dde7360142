// The water as a participating medium, seen from inside it. Red is absorbed fastest,
// blue-green slowest, so light that has crossed metres of water turns blue-green; the
// light scattered towards the eye comes from above and fades with the viewer's depth.

uniform vec3 uWaterScatter;
uniform float uFogDensity;
// uWaterScatter times the daylight left at the eye's depth (exp(-DEPTH_DARKENING · depth)),
// made on the CPU once a frame (src/render/underwater/waterVolumeUniforms.ts) rather than three
// exponentials of the same uniform per pixel (perf: docs/shader-notes.md).
uniform vec3 uWaterAtEye;

// Per-channel extinction relative to uFogDensity (WATER_EXTINCTION) and the daylight's fading
// with depth per metre (DEPTH_DARKENING): <oceano_constants>, from src/sim/underwater/waterFog.ts, which
// also tells how far the fog lets anything be seen.
#include <oceano_constants>

vec3 waterTransmittance(float distance) {
  return exp(-uFogDensity * WATER_EXTINCTION * distance);
}

// The colour of an infinitely long line of sight through the water in a direction.
vec3 waterVolumeColor(vec3 direction) {
  float up = 0.5 + 0.5 * direction.y;
  float fromAbove = mix(0.22, 1.0, up * up);
  return uWaterAtEye * fromAbove;
}

vec3 throughWater(vec3 color, vec3 direction, float distance) {
  vec3 transmittance = waterTransmittance(distance);
  return color * transmittance + waterVolumeColor(direction) * (1.0 - transmittance);
}
