// The water as a participating medium, seen from inside it. Red is absorbed fastest,
// blue-green slowest, so light that has crossed metres of water turns blue-green; the
// light scattered towards the eye comes from above and fades with the viewer's depth.

uniform vec3 uWaterScatter;
uniform float uFogDensity;
uniform float uCameraDepth;

// Per-channel extinction relative to uFogDensity, WATER_EXTINCTION: <oceano_constants>, from
// src/sim/waterFog.ts, which also tells how far the fog lets anything be seen.
#include <oceano_constants>
// How fast daylight fades with depth, per metre, per channel.
const vec3 DEPTH_DARKENING = vec3(0.12, 0.045, 0.03);

vec3 waterTransmittance(float distance) {
  return exp(-uFogDensity * WATER_EXTINCTION * distance);
}

// The colour of an infinitely long line of sight through the water in a direction.
vec3 waterVolumeColor(vec3 direction) {
  float up = 0.5 + 0.5 * direction.y;
  float fromAbove = mix(0.22, 1.0, up * up);
  return uWaterScatter * fromAbove * exp(-DEPTH_DARKENING * max(uCameraDepth, 0.0));
}

vec3 throughWater(vec3 color, vec3 direction, float distance) {
  vec3 transmittance = waterTransmittance(distance);
  return color * transmittance + waterVolumeColor(direction) * (1.0 - transmittance);
}
