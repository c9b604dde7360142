// Caustics: the bright net of light under waves. Needs <oceano_waves> first.
// Sunlight is refracted through the displaced surface (its real normals, Snell's law)
// and followed down to the depth of the lit point; the ratio of a small patch's area on
// the surface to the area it lands on is the concentration of light there (the inverse
// Jacobian of the surface-to-floor map). Folds of that map are the bright lines.

uniform vec3 uCausticsSunDirection; // unit vector towards the sun, in the air
uniform vec3 uCausticsRefractedSun; // the sunlight's direction under a flat sea (from the CPU)
uniform float uCausticsStrength;    // 0: flat light, 1: physical concentration

#include <oceano_constants>

const float CAUSTICS_AIR_OVER_WATER = 1.0 / WATER_IOR;
// Side of the surface patch whose image is measured, metres.
const float CAUSTICS_PATCH = 0.75;
// Brightest concentration kept: a fold of the map is a line of infinite intensity.
const float CAUSTICS_MAX_GAIN = 8.0;

// Where light through the surface point displaced from grid point s lands at depth floorY.
vec2 causticLanding(vec2 s, float floorY, vec3 light) {
  vec3 d = waveDisplacement(s);
  vec3 n = waveNormal(s);
  vec3 t = refract(light, n, CAUSTICS_AIR_OVER_WATER);
  return s + d.xz + t.xz * ((floorY - d.y) / min(t.y, -1e-3));
}

// Multiplier of the direct sunlight reaching a point under the water (1 where the sea is
// flat, above 1 where waves focus light, below where they spread it). Points above the
// surface, and a sun below the horizon, get 1: there is nothing to concentrate.
float causticLight(vec3 p) {
  if (uCausticsSunDirection.y <= 0.0 || uCausticsStrength <= 0.0) return 1.0;
  // Above the surface (the grid point under p stands for the world point: exact for models
  // that only lift points, within the horizontal displacement's reach for choppy ones).
  // CAUSTICS_BELOW_WAVES: the caller's points all lie below the deepest trough (the sea bed
  // deeper than the model's bound, src/render/underwater/seaBed.ts), and the test is compiled out.
#ifndef CAUSTICS_BELOW_WAVES
  if (p.y >= waveDisplacement(p.xz).y) return 1.0;
#endif
  vec3 light = -uCausticsSunDirection;
  vec3 flatRay = uCausticsRefractedSun;
  // The surface point above p along the ray a flat sea would send there.
  vec2 s = p.xz - flatRay.xz * (p.y / flatRay.y);
  vec2 a = causticLanding(s, p.y, light);
  vec2 b = causticLanding(s + vec2(CAUSTICS_PATCH, 0.0), p.y, light);
  vec2 c = causticLanding(s + vec2(0.0, CAUSTICS_PATCH), p.y, light);
  vec2 ab = b - a;
  vec2 ac = c - a;
  float landedArea = abs(ab.x * ac.y - ab.y * ac.x);
  float patchArea = CAUSTICS_PATCH * CAUSTICS_PATCH;
  float gain = patchArea / max(landedArea, patchArea / CAUSTICS_MAX_GAIN);
  // Above an intensity of 1 the mix would go below zero where the light spreads: no light is less than none.
  return max(mix(1.0, gain, uCausticsStrength), 0.0);
}
