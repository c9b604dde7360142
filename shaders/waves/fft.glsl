// The spectral sea as a wave-model chunk (`#include <oceano_waves>` resolves here when
// waves=fft; see src/render/waves/fft/fftWaveView.ts). Three cascades (FFT tiles of
// different sizes, src/sim/waves/fft/cascades.ts), each two RGBA32F textures written by the GPU FFT
// (src/render/waves/fft/gpuFft.ts):
//   uFftDisplacementC: (dx, dy, dz, ∂Dx/∂x)    uFftDerivativesC: (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
// Texel (p, q) of a tile of side L is the grid point (p L/n, q L/n); tiles repeat. Each field
// is read bilinearly by hand (texelFetch: float textures need not be filterable), exactly as
// the CPU twin src/sim/waves/fft/fftOcean.ts reads its float64 arrays: a parity test holds them together.
//
// The contract every model's chunk meets:
//   vec3 waveDisplacement(vec2 gridXZ)  where the undisplaced grid point goes, (dx, dy, dz)
//   vec3 waveNormal(vec2 gridXZ)        unit normal of the displaced surface there
//   float waveLensHeight(vec2 worldXZ)  the short waves' height (focuses the god rays)
// and, this model only (ocean.frag tests the defines):
//   WAVE_PIXEL_NORMALS: waveNormal is exact (from spectral slopes): evaluate it per pixel,
//     after wavePixelFields has read this pixel's fields
//   WAVE_FOAM: float waveFoam(vec2 gridXZ), foam coverage in [0, 1]
//   WAVE_FABRICATED_NORMAL: vec3 waveFabricatedNormal(vec2 gridXZ), the seed's finite-
//     difference normal of the same surface, for the comparison teaching view

#define WAVE_PIXEL_NORMALS
#define WAVE_FOAM
#define WAVE_FABRICATED_NORMAL

uniform sampler2D uFftDisplacement0;
uniform sampler2D uFftDisplacement1;
uniform sampler2D uFftDisplacement2;
uniform sampler2D uFftDerivatives0;
uniform sampler2D uFftDerivatives1;
uniform sampler2D uFftDerivatives2;
uniform sampler2D uFftFoam0;
uniform sampler2D uFftFoam1;
uniform sampler2D uFftFoam2;
uniform vec3 uFftScale;      // n / L per cascade: texels per metre
// Per cascade, where the render origin falls in its tile, in texels, within [0, n) (reduced in
// double precision, src/sim/waves/originPhases.ts): the pixels read their fields at grid points
// relative to the render origin (waveNormalNear, waveFoamNear), since an absolute float32
// grid point 10⁶ m out is rounded to 6 cm and its normals came in 6 cm blocks.
uniform vec2 uFftNearOffset[3];
uniform float uFftN;
uniform float uFoamEnabled;  // 0 or 1
uniform float uFoamThreshold;
uniform float uFoamSoftness;   // half-width of the soft edge around the threshold
uniform float uFabricatedDelta;

// The CPU twin's bilinear read: u = x n/L, texel floor(u) mod n and the next, weights fract(u).
// `offset` (texels) is 0 for an absolute grid point, the cascade's uFftNearOffset for one
// relative to the render origin.
vec4 fftBilinear(sampler2D map, vec2 p, float scale, vec2 offset) {
  vec2 u = p * scale + offset;
  vec2 f = floor(u);
  vec2 w = u - f;
  int n = int(uFftN);
  ivec2 i0 = ivec2(mod(f, uFftN));
  ivec2 i1 = (i0 + 1) % n;
  vec4 a = texelFetch(map, i0, 0);
  vec4 b = texelFetch(map, ivec2(i1.x, i0.y), 0);
  vec4 c = texelFetch(map, ivec2(i0.x, i1.y), 0);
  vec4 d = texelFetch(map, i1, 0);
  vec4 top = a + (b - a) * w.x;
  vec4 bottom = c + (d - c) * w.x;
  return top + (bottom - top) * w.y;
}

// The ocean's pixels (ocean.frag defines WAVE_FRAGMENT_STAGE) read the fields through the
// texture unit's own bilinear filter when float textures are filterable
// (OES_texture_float_linear; fftWaveView.ts then defines FFT_FILTERED_FIELDS and makes the
// targets LINEAR): one filtered read per field instead of four texelFetch and their weights.
// Texel (p, q) sits at the grid point (p, q) L/n,
// i.e. at texture coordinate (p + ½)/n, hence the half texel. Only normals and foam are read
// this way; positions (the vertex stage, the boat's twin, caustics) keep the exact reads
// above, so the 1 mm parity with the CPU twin is untouched. The filter's weights may be
// coarser than float32 (GPUs commonly keep 8 fractional bits): a slope error of at most 1/256
// of the change across one texel, invisible in a normal.
#if defined(FFT_FILTERED_FIELDS) && defined(WAVE_FRAGMENT_STAGE)
vec4 fftField(sampler2D map, vec2 p, float scale, vec2 offset) {
  return texture(map, (p * scale + offset + 0.5) / uFftN);
}
#else
vec4 fftField(sampler2D map, vec2 p, float scale, vec2 offset) {
  return fftBilinear(map, p, scale, offset);
}
#endif

// Cascade c's texel offset for a point that is absolute (near false) or relative to the render origin.
vec2 fftOffset(int c, bool near) {
  return near ? uFftNearOffset[c] : vec2(0.0);
}

// One field of the whole sea: the three cascades' tiles, each read at its own scale, summed.
vec4 fftCascadeSum(sampler2D cascade0, sampler2D cascade1, sampler2D cascade2, vec2 p, bool near) {
  return fftField(cascade0, p, uFftScale.x, fftOffset(0, near)) + fftField(cascade1, p, uFftScale.y, fftOffset(1, near))
    + fftField(cascade2, p, uFftScale.z, fftOffset(2, near));
}

#ifdef WAVE_FRAGMENT_STAGE
// The ocean's pixels: every field a pixel needs is read once, at the top of ocean.frag's main
// (wavePixelFields), outside any branch, and the normal and foam below only combine them.
// perf: a "read only if not cached" branch would read the textures again on a software
// rasterizer, which runs both sides of a branch (docs/shader-notes.md).
// Per cascade: the derivatives texture (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z) and the foam texture
// (foam potential, J, ∂Dx/∂x) (shaders/fftFoam.frag): 6 reads per pixel.
vec4 fftPixelDerivatives;
float fftPixelJxx;
vec2 fftPixelPotentials;

void fftReadPixelFields(vec2 p, bool near) {
  fftPixelDerivatives = fftCascadeSum(uFftDerivatives0, uFftDerivatives1, uFftDerivatives2, p, near);
  vec4 foam0 = fftField(uFftFoam0, p, uFftScale.x, fftOffset(0, near));
  vec4 foam1 = fftField(uFftFoam1, p, uFftScale.y, fftOffset(1, near));
  vec4 foam2 = fftField(uFftFoam2, p, uFftScale.z, fftOffset(2, near));
  fftPixelJxx = foam0.b + foam1.b + foam2.b;
  fftPixelPotentials = vec2(foam1.r, foam2.r);
}

// ocean.frag's hook: p is the pixel's grid point relative to the render origin (near) or absolute.
void wavePixelFields(vec2 p, bool near) {
  fftReadPixelFields(p, near);
}

// The point arguments are those wavePixelFields was given (ocean.frag passes the same).
vec4 fftDerivativeFields(vec2 p, bool near) {
  return fftPixelDerivatives;
}

float fftJxx(vec2 p, bool near) {
  return fftPixelJxx;
}

vec2 fftFoamPotentials(vec2 p, bool near) {
  return fftPixelPotentials;
}

vec4 fftDisplacementFields(vec2 p, bool near) {
  return fftCascadeSum(uFftDisplacement0, uFftDisplacement1, uFftDisplacement2, p, near);
}
#else
// The vertices: the last grid point's displacement sums, kept per shader invocation, so a
// vertex that asks for the displacement and then the normal (comparison view) reads once.
// The key is the point and whether it is relative to the render origin (z: 1) or not (0).
vec3 fftDisplacementPoint = vec3(3.0e38);
vec4 fftCachedDisplacement;

vec4 fftDisplacementFields(vec2 p, bool near) {
  vec3 key = vec3(p, near ? 1.0 : 0.0);
  if (key != fftDisplacementPoint) {
    fftDisplacementPoint = key;
    fftCachedDisplacement = fftCascadeSum(uFftDisplacement0, uFftDisplacement1, uFftDisplacement2, p, near);
  }
  return fftCachedDisplacement;
}

vec4 fftDerivativeFields(vec2 p, bool near) {
  return fftCascadeSum(uFftDerivatives0, uFftDerivatives1, uFftDerivatives2, p, near);
}

// ∂Dx/∂x of the whole sea at a grid point.
float fftJxx(vec2 p, bool near) {
  return fftDisplacementFields(p, near).w;
}

// Each remembering cascade's foam potential at a grid point (cascades 1 and 2).
vec2 fftFoamPotentials(vec2 p, bool near) {
  return vec2(fftField(uFftFoam1, p, uFftScale.y, fftOffset(1, near)).r, fftField(uFftFoam2, p, uFftScale.z, fftOffset(2, near)).r);
}
#endif

vec3 waveDisplacement(vec2 gridXZ) {
  return fftDisplacementFields(gridXZ, false).xyz;
}

// Normal of P(x, z) = (x + Dx, h, z + Dz): ∂P/∂z × ∂P/∂x with every derivative exact from the
// spectrum (i k h, −λ k k̂ h), as FftOcean.normalAt.
vec3 fftNormal(vec2 p, bool near) {
  float jxx = fftJxx(p, near);
  vec4 d = fftDerivativeFields(p, near);
  vec3 tx = vec3(1.0 + jxx, d.x, d.w);
  vec3 tz = vec3(d.w, d.y, 1.0 + d.z);
  return normalize(cross(tz, tx));
}

vec3 waveNormal(vec2 gridXZ) {
  return fftNormal(gridXZ, false);
}

// The normal at the grid point uRenderOrigin + relativeXZ (the render origin is ocean.vert's).
vec3 waveNormalNear(vec2 relativeXZ) {
  return fftNormal(relativeXZ, true);
}

// The seed's way on this sea: neighbours a small step away, their displaced positions
// differenced. What the teaching view puts beside the exact normal.
vec3 waveFabricatedNormal(vec2 gridXZ) {
  float s = uFabricatedDelta;
  vec3 p0 = vec3(gridXZ.x, 0.0, gridXZ.y) + waveDisplacement(gridXZ);
  vec3 px = vec3(gridXZ.x + s, 0.0, gridXZ.y) + waveDisplacement(gridXZ + vec2(s, 0.0));
  vec3 pz = vec3(gridXZ.x, 0.0, gridXZ.y + s) + waveDisplacement(gridXZ + vec2(0.0, s));
  return normalize(cross(pz - p0, px - p0));
}

// Foam: what each cascade accumulated (fading over seconds, src/render/waves/fft/fftFoam.ts, each
// against its own band's threshold) and where the whole sea's Jacobian folds right now, half
// white at the threshold itself (so Monahan's share of the sea is at least half white) and
// fully white ¼σ deeper.
float fftFoamAt(vec2 p, bool near) {
  float jxx = fftJxx(p, near);
  vec4 d = fftDerivativeFields(p, near);
  float jacobian = (1.0 + jxx) * (1.0 + d.z) - d.w * d.w;
  float now = smoothstep(uFoamThreshold + uFoamSoftness, uFoamThreshold - uFoamSoftness, jacobian);
  // The largest tile's foam is left out: its texels are tens of metres wide (22 m in a gale),
  // which drew soft white blotches; breaking happens at the scale of the shorter waves.
  // Each stores a foam potential (1 at its threshold, shaders/fftFoam.frag): white from 1 on.
  vec2 potentials = fftFoamPotentials(p, near);
  float potential = max(potentials.x, potentials.y);
  // A wide ramp: foam left behind thins out as it fades (translucent, then gone) instead of
  // shrinking as a hard-edged white floe.
  float kept = smoothstep(0.5, 1.5, potential);
  return uFoamEnabled * clamp(max(now, kept), 0.0, 1.0);
}

float waveFoam(vec2 gridXZ) {
  return fftFoamAt(gridXZ, false);
}

// Foam at the grid point uRenderOrigin + relativeXZ.
float waveFoamNear(vec2 relativeXZ) {
  return fftFoamAt(relativeXZ, true);
}

// The shortest cascade's height: metre-scale bumps that focus sunlight into shafts.
float waveLensHeight(vec2 worldXZ) {
  return fftBilinear(uFftDisplacement2, worldXZ, uFftScale.z, vec2(0.0)).y;
}
