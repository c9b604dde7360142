// The Gerstner sea as a wave-model chunk (`#include <oceano_waves>` resolves here when
// waves=gerstner; see src/render/waves/): the GLSL twin of src/sim/waves/gerstner/gerstnerWaves.ts
// (gerstnerDisplacementAt, gerstnerNormalAt). Keep the two in step: parity tests compare them.
//
// The contract every model's chunk meets:
//   vec3 waveDisplacement(vec2 gridXZ)  where the undisplaced grid point goes, (dx, dy, dz)
//   vec3 waveNormal(vec2 gridXZ)        unit normal of the displaced surface there
//   float waveLensHeight(vec2 worldXZ)  the short waves' height, whose bumps focus sunlight
//                                       into the underwater shafts (god rays)
// and, because the normal is closed-form and cheap, it asks ocean.frag to evaluate
// waveNormalNear per pixel at the interpolated grid point (WAVE_PIXEL_NORMALS), given
// relative to the render origin (src/render/ocean/renderOrigin.ts): an absolute float32 grid point
// 10⁶ m out is rounded to 6 cm, which put the glint in 6 cm blocks.
//
// Wave i moves grid point p to p + (−QᵢAᵢ k̂ᵢ sin θᵢ, Aᵢ cos θᵢ), θᵢ = kᵢ·p − ωᵢt + φᵢ.
// Angles are in turns. The time part τᵢ = fract(φᵢ − ωᵢt/2π) arrives already reduced in
// double precision (gerstnerTimePhases), so float32 stays exact at t = 10⁶ s; the space
// part is fract(cₓ x) + fract(c_z z), which drops the integer turns before they cost bits.

#define GERSTNER_MAX_WAVES 64
#define WAVE_PIXEL_NORMALS

uniform int uGerstnerCount;
// Per wave: (cₓ, c_z) the wavevector in cycles per metre, A the amplitude (m), QA the
// horizontal amplitude (m).
uniform vec4 uGerstnerWaves[GERSTNER_MAX_WAVES];
// τᵢ in turns, four waves per vec4 (a float array would take a whole vec4 slot per element).
uniform vec4 uGerstnerPhases[GERSTNER_MAX_WAVES / 4];
// τᵢ′ = fract(τᵢ + cₓ oₓ + c_z o_z), the phases at the render origin o, reduced in double
// precision (src/sim/waves/originPhases.ts): the angle at o + r is fract(cₓ rₓ) + fract(c_z r_z) + τᵢ′.
uniform vec4 uGerstnerNearPhases[GERSTNER_MAX_WAVES / 4];

#include <oceano_sin_turns>

float gerstnerTurns(vec4 wave, float tau, vec2 p) {
  return fract(wave.x * p.x) + fract(wave.y * p.y) + tau;
}

float gerstnerPhase(int i) {
  return uGerstnerPhases[i >> 2][i & 3];
}

float gerstnerNearPhase(int i) {
  return uGerstnerNearPhases[i >> 2][i & 3];
}

vec3 waveDisplacement(vec2 gridXZ) {
  vec3 d = vec3(0.0);
  for (int i = 0; i < GERSTNER_MAX_WAVES; i++) {
    if (i >= uGerstnerCount) break;
    vec4 wave = uGerstnerWaves[i];
    float turns = gerstnerTurns(wave, gerstnerPhase(i), gridXZ);
    float s = sinTurns(turns);
    float c = sinTurns(turns + 0.25);
    vec2 dir = wave.xy / length(wave.xy);
    d.x -= wave.w * dir.x * s;
    d.z -= wave.w * dir.y * s;
    d.y += wave.z * c;
  }
  return d;
}

// Closed-form derivatives (see gerstnerDerivativesAt): the tangents ∂P/∂x, ∂P/∂z of the
// displaced surface P = (x + dx, dy, z + dz), and their cross product. `near`: p is relative
// to the render origin (a constant at each call, so the choice folds away).
vec3 gerstnerNormal(vec2 p, bool near) {
  float dxdx = 0.0;
  float dxdz = 0.0;
  float dzdz = 0.0;
  float dydx = 0.0;
  float dydz = 0.0;
  for (int i = 0; i < GERSTNER_MAX_WAVES; i++) {
    if (i >= uGerstnerCount) break;
    vec4 wave = uGerstnerWaves[i];
    float turns = gerstnerTurns(wave, near ? gerstnerNearPhase(i) : gerstnerPhase(i), p);
    float s = sinTurns(turns);
    float c = sinTurns(turns + 0.25);
    vec2 k = TURN_RADIANS * wave.xy;
    float qc = wave.w / length(k) * c;
    dxdx -= qc * k.x * k.x;
    dxdz -= qc * k.x * k.y;
    dzdz -= qc * k.y * k.y;
    float aSin = wave.z * s;
    dydx -= aSin * k.x;
    dydz -= aSin * k.y;
  }
  vec3 tx = vec3(1.0 + dxdx, dydx, dxdz);
  vec3 tz = vec3(dxdz, dydz, 1.0 + dzdz);
  return normalize(cross(tz, tx));
}

vec3 waveNormal(vec2 gridXZ) {
  return gerstnerNormal(gridXZ, false);
}

// The normal at the grid point uRenderOrigin + relativeXZ (the render origin is ocean.vert's).
vec3 waveNormalNear(vec2 relativeXZ) {
  return gerstnerNormal(relativeXZ, true);
}

// ocean.frag reads a per-pixel model's fields first (wavePixelFields); the closed-form normal
// reads only uniforms, so there is nothing to read ahead.
void wavePixelFields(vec2 relativeXZ, bool near) {}

// Waves shorter than this focus sunlight within the god-ray shafts' few metres; longer ones
// only tilt the whole shaft field. Their height is taken at the world point itself (their
// horizontal motion, a fraction of a metre, moves the shafts, not their pattern).
const float GERSTNER_LENS_WAVELENGTH = 12.0;

float waveLensHeight(vec2 worldXZ) {
  float h = 0.0;
  for (int i = 0; i < GERSTNER_MAX_WAVES; i++) {
    if (i >= uGerstnerCount) break;
    vec4 wave = uGerstnerWaves[i];
    if (dot(wave.xy, wave.xy) * GERSTNER_LENS_WAVELENGTH * GERSTNER_LENS_WAVELENGTH < 1.0) continue;
    h += wave.z * sinTurns(gerstnerTurns(wave, gerstnerPhase(i), worldXZ) + 0.25);
  }
  return h;
}
