// The Gerstner sea as a wave-model chunk (`#include <oceano_waves>` resolves here when
// waves=gerstner; see src/render/waves/): the GLSL twin of src/sim/waves/gerstner/gerstnerWaves.ts
// (gerstnerDisplacementAt, gerstnerNormalAt). Keep the two in step: parity tests compare them.
//
// The contract every model's chunk meets:
//   vec3 waveDisplacement(vec2 gridXZ)  where the undisplaced grid point goes, (dx, dy, dz)
//   vec3 waveNormal(vec2 gridXZ)        unit normal of the displaced surface there
//   float waveLensHeight(vec2 worldXZ)  the short waves' height, whose bumps focus sunlight
//                                       into the underwater shafts (god rays)
//   float waveUnresolvedSlopeVariance()  (ocean.frag's pixels) the slopes the normal leaves
//                                       out, the glint's and the sky reflection's roughness
// and, because the normal is closed-form, it asks ocean.frag to evaluate waveNormalNear per
// pixel at the interpolated grid point (WAVE_PIXEL_NORMALS), given relative to the render
// origin (src/render/ocean/renderOrigin.ts): an absolute float32 grid point 10⁶ m out is
// rounded to 6 cm, which put the glint in 6 cm blocks. Only the short waves are summed per
// pixel: the long ones, whose derivatives a triangle interpolates to within 0.02 of slope,
// are summed per vertex (WAVE_VERTEX_SLOPES, ocean.vert) in the displacement's own sum.
//
// Wave i moves grid point p to p + (−QᵢAᵢ k̂ᵢ sin θᵢ, Aᵢ cos θᵢ), θᵢ = kᵢ·p − ωᵢt + φᵢ.
// Angles are in turns. The time part τᵢ = fract(φᵢ − ωᵢt/2π) arrives already reduced in
// double precision (gerstnerTimePhases), so float32 stays exact at t = 10⁶ s; the space
// part is fract(cₓ x) + fract(c_z z), which drops the integer turns before they cost bits.

#define GERSTNER_MAX_WAVES 64
#define WAVE_PIXEL_NORMALS
#define WAVE_VERTEX_SLOPES

uniform int uGerstnerCount;
// Per wave, longest first (src/render/waves/gerstner/gerstnerWaveUniforms.ts): (cₓ, c_z) the
// wavevector in cycles per metre, A the amplitude (m), QA the horizontal amplitude (m).
uniform vec4 uGerstnerWaves[GERSTNER_MAX_WAVES];
// τᵢ in turns, four waves per vec4 (a float array would take a whole vec4 slot per element).
uniform vec4 uGerstnerPhases[GERSTNER_MAX_WAVES / 4];
// τᵢ′ = fract(τᵢ + cₓ oₓ + c_z o_z), the phases at the render origin o, reduced in double
// precision (src/sim/waves/originPhases.ts): the angle at o + r is fract(cₓ rₓ) + fract(c_z r_z) + τᵢ′.
uniform vec4 uGerstnerNearPhases[GERSTNER_MAX_WAVES / 4];
// Each wave's mean-square slope (src/sim/waves/gerstner/gerstnerSlopes.ts), four per vec4, and
// the sea's, Cox & Munk's for the wind (src/sim/optics/coxMunk.ts): what the normals do not
// show of it is the glint's roughness.
uniform vec4 uGerstnerSlopes[GERSTNER_MAX_WAVES / 4];
uniform float uSeaSlopeVariance;
// Radians of view per pixel: the vertices' estimate of a pixel's footprint on the sea.
uniform float uPixelAngle;

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

// The share of a wave's slope that a pixel `footprint` metres across resolves: all of it
// while two pixels fit in its wavelength, none once one pixel spans it, in between by the
// octave (the FFT sea's resolvedShare for a band one octave wide, src/sim/optics/resolvedSlopes.ts).
// What a pixel does not resolve would only alias (the fringe at the horizon); it goes into
// the glint's roughness instead (Bruneton, Neyret & Holzschuch 2010).
float gerstnerShare(vec4 wave, float footprint) {
  return clamp(log2(1.0 / (length(wave.xy) * 2.0 * footprint)) + 0.5, 0.0, 1.0);
}

// Wave `wave`'s closed-form derivatives (see gerstnerDerivativesAt) at the angle whose sine
// and cosine are s and c, times `share`, added to (∂dx/∂x, ∂dx/∂z, ∂dz/∂z, ∂dy/∂x) and ∂dy/∂z.
void gerstnerAddDerivatives(vec4 wave, float s, float c, float share, inout vec4 horizontal, inout float dydz) {
  vec2 k = TURN_RADIANS * wave.xy;
  float qc = share * wave.w / length(k) * c;
  float aSin = share * wave.z * s;
  horizontal -= vec4(qc * k.x * k.x, qc * k.x * k.y, qc * k.y * k.y, aSin * k.x);
  dydz -= aSin * k.y;
}

float gerstnerSlope(int i) {
  return uGerstnerSlopes[i >> 2][i & 3];
}

#if defined(WAVE_VERTEX_STAGE) || defined(WAVE_FRAGMENT_STAGE)
// From the vertices to the pixels: the first wave summed per pixel (the same for a whole
// chunk, whose vertex step is one), the per-vertex waves' filtered derivatives (as
// gerstnerAddDerivatives) and the slope variance they resolve.
flat varying int vGerstnerFirstPixelWave;
varying vec4 vGerstnerHorizontal;
varying vec2 vGerstnerDydzAndVariance;
#endif

#ifdef WAVE_VERTEX_STAGE
// Set by ocean.vert before it asks for the displacement: the chunk's vertex step, m, and the
// way from the vertex to the eye.
float waveVertexSpacing;
vec3 waveVertexToEye;

// Linear interpolation across a triangle, whose sides reach s√2 along a wave, misses a slope of
// amplitude a by at most a (k s √2)² / 8 = a (ks)² / 4: a wave's derivatives are summed per
// vertex, from the longest on, while that stays within this (1.1°, well inside the glint's
// roughness, √(σ²/2) ≈ 0.1 per axis at any wind), and per pixel from the first that misses by more.
const float GERSTNER_VERTEX_SLOPE_ERROR = 0.02;
#endif

// Wave i's trochoid at a grid point added to d: its points circle, back along the wave's
// direction and up; returns the phase's (sin, cos), which the derivatives reuse.
vec2 gerstnerAddDisplacement(int i, vec2 gridXZ, inout vec3 d) {
  vec4 wave = uGerstnerWaves[i];
  float turns = gerstnerTurns(wave, gerstnerPhase(i), gridXZ);
  float s = sinTurns(turns);
  float c = sinTurns(turns + 0.25);
  vec2 dir = wave.xy / length(wave.xy);
  d.x -= wave.w * dir.x * s;
  d.z -= wave.w * dir.y * s;
  d.y += wave.z * c;
  return vec2(s, c);
}

vec3 waveDisplacement(vec2 gridXZ) {
  vec3 d = vec3(0.0);
  for (int i = 0; i < GERSTNER_MAX_WAVES; i++) {
    if (i >= uGerstnerCount) break;
    gerstnerAddDisplacement(i, gridXZ, d);
  }
  return d;
}

#ifdef WAVE_VERTEX_STAGE
// The same sum for the ocean's vertices (ocean.vert, WAVE_VERTEX_SLOPES), which also takes the
// derivatives of the waves the vertices may interpolate (see GERSTNER_VERTEX_SLOPE_ERROR), each
// by the share a pixel there resolves: a pixel spans about distance × uPixelAngle across the
// view and that over the sine of the grazing angle along it; the longer side decides, as in
// the pixels. The first loop ends at the same wave for a whole chunk (its vertex step is one).
vec3 waveVertexDisplacement(vec2 gridXZ) {
  float distance = length(waveVertexToEye);
  float footprint = distance * uPixelAngle / max(abs(waveVertexToEye.y) / distance, 1e-3);
  vec3 d = vec3(0.0);
  vec4 horizontal = vec4(0.0);
  float dydz = 0.0;
  float variance = 0.0;
  int i = 0;
  // The long waves: displacement and derivatives, until the first a triangle cannot interpolate.
  for (; i < GERSTNER_MAX_WAVES; i++) {
    if (i >= uGerstnerCount) break;
    vec4 wave = uGerstnerWaves[i];
    float cycles = length(wave.xy);
    float ks = TURN_RADIANS * cycles * waveVertexSpacing;
    if (max(wave.z, wave.w) * TURN_RADIANS * cycles * ks * ks > 4.0 * GERSTNER_VERTEX_SLOPE_ERROR) break;
    vec2 sc = gerstnerAddDisplacement(i, gridXZ, d);
    float share = gerstnerShare(wave, footprint);
    gerstnerAddDerivatives(wave, sc.x, sc.y, share, horizontal, dydz);
    variance += share * share * gerstnerSlope(i);
  }
  vGerstnerFirstPixelWave = i;
  // The rest: displacement only (their slopes are the pixels').
  for (; i < GERSTNER_MAX_WAVES; i++) {
    if (i >= uGerstnerCount) break;
    gerstnerAddDisplacement(i, gridXZ, d);
  }
  vGerstnerHorizontal = horizontal;
  vGerstnerDydzAndVariance = vec2(dydz, variance);
  return d;
}
#endif

// The tangents ∂P/∂x, ∂P/∂z of the displaced surface P = (x + dx, dy, z + dz), and their cross product.
vec3 gerstnerNormalFrom(vec4 horizontal, float dydz) {
  vec3 tx = vec3(1.0 + horizontal.x, horizontal.w, horizontal.y);
  vec3 tz = vec3(horizontal.y, dydz, 1.0 + horizontal.z);
  return normalize(cross(tz, tx));
}

// Wave i's derivatives at grid point p, times `share`. `near`: p is relative to the render
// origin (a constant at each call, so the choice folds away).
void gerstnerAddWave(int i, vec2 p, bool near, float share, inout vec4 horizontal, inout float dydz) {
  float turns = gerstnerTurns(uGerstnerWaves[i], near ? gerstnerNearPhase(i) : gerstnerPhase(i), p);
  gerstnerAddDerivatives(uGerstnerWaves[i], sinTurns(turns), sinTurns(turns + 0.25), share, horizontal, dydz);
}

// The whole sum at a grid point, unfiltered: the vertices' and other programs' normal (the probe, caustics).
vec3 gerstnerFullNormal(vec2 p, bool near) {
  vec4 horizontal = vec4(0.0);
  float dydz = 0.0;
  for (int i = 0; i < GERSTNER_MAX_WAVES; i++) {
    if (i >= uGerstnerCount) break;
    gerstnerAddWave(i, p, near, 1.0, horizontal, dydz);
  }
  return gerstnerNormalFrom(horizontal, dydz);
}

#ifdef WAVE_FRAGMENT_STAGE
// The pixel's footprint on the sea, m, read once at the top of ocean.frag's main (outside its
// branches, where derivatives are defined): the longer side, as the FFT sea's.
float gerstnerFootprint;
float gerstnerUnresolvedVariance;

void wavePixelFields(vec2 p, bool near) {
  gerstnerFootprint = max(max(length(dFdx(p)), length(dFdy(p))), 1e-6);
  // Where no normal is evaluated (the flat-normals teaching view) every slope is roughness.
  gerstnerUnresolvedVariance = uSeaSlopeVariance;
}

// The per-vertex waves, interpolated, plus the short ones summed here, each by the share this
// pixel resolves; the waves are longest first, so the loop ends at the first one it cannot.
vec3 gerstnerNormal(vec2 p, bool near) {
  vec4 horizontal = vGerstnerHorizontal;
  float dydz = vGerstnerDydzAndVariance.x;
  float variance = vGerstnerDydzAndVariance.y;
  for (int i = vGerstnerFirstPixelWave; i < uGerstnerCount; i++) {
    float share = gerstnerShare(uGerstnerWaves[i], gerstnerFootprint);
    if (share <= 0.0) break;
    gerstnerAddWave(i, p, near, share, horizontal, dydz);
    variance += share * share * gerstnerSlope(i);
  }
  gerstnerUnresolvedVariance = max(SUN_DISC_SLOPE_VARIANCE, uSeaSlopeVariance - variance);
  return gerstnerNormalFrom(horizontal, dydz);
}

// The mean-square slope of the waves this pixel's normal does not show (after waveNormalNear).
float waveUnresolvedSlopeVariance() {
  return gerstnerUnresolvedVariance;
}
#else
vec3 gerstnerNormal(vec2 p, bool near) {
  return gerstnerFullNormal(p, near);
}
#endif

vec3 waveNormal(vec2 gridXZ) {
  return gerstnerNormal(gridXZ, false);
}

// The normal at the grid point uRenderOrigin + relativeXZ (the render origin is ocean.vert's).
vec3 waveNormalNear(vec2 relativeXZ) {
  return gerstnerNormal(relativeXZ, true);
}

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
