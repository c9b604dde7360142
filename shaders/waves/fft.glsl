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
//   float waveUnresolvedSlopeVariance()  (ocean.frag's pixels) the mean-square slope of the
//                                       waves this pixel's normal does not show, which the
//                                       sun's glint and the sky's reflection take as roughness
// and, this model only (ocean.frag tests the defines):
//   WAVE_PIXEL_NORMALS: waveNormal is exact (from spectral slopes): evaluate it per pixel,
//     after wavePixelFields has read this pixel's fields
//   WAVE_FOAM: float waveFoam(vec2 gridXZ), foam coverage in [0, 1]
//   WAVE_FABRICATED_NORMAL: vec3 waveFabricatedNormal(vec2 gridXZ), the seed's finite-
//     difference normal of the same surface, for the comparison teaching view
//   WAVE_PINCH: float wavePinch(), how pinched the surface is at this pixel, 1 − J in [0, 1]
//     (the subsurface glow, shaders/subsurface.glsl)

#define WAVE_PIXEL_NORMALS
#define WAVE_FOAM
#define WAVE_FABRICATED_NORMAL
#define WAVE_PINCH

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
uniform float uFoamThreshold;  // the whole sea's breaking threshold, breakup shift included (fftWaveView.ts)
uniform float uFoamSoftness;   // half-width of the soft edge around the threshold
uniform float uFoamBreakupStrength;  // the breakup field's weight, in units of the breaking measure
uniform float uFabricatedDelta;
// Per cascade: the mean-square slope of its waves (both axes), the logarithm of its longest
// wavelength (m) and 1 / ln(longest / shortest), its band's width in e-folds; and the whole
// sea's mean-square slope, Cox & Munk's for this wind (src/sim/optics/coxMunk.ts), of which the
// cascades resolve only the waves longer than a metre or so.
uniform vec3 uFftSlopeVariance;
uniform vec3 uFftLogLongestWave;
uniform vec3 uFftPerLogBand;
uniform float uSeaSlopeVariance;

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
// perf: one read of each field, with no branch around it, on any GPU; a "read only if not
// cached" branch would read the textures again on a software rasterizer, which runs both
// sides of a branch (docs/shader-notes.md).
// Per cascade: the derivatives texture (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z) and the packed texture
// (remembered foam, 0, ∂Dx/∂x) (shaders/fftFoam.frag): 6 reads per pixel.
//
// Seamless from geometry to roughness (Bruneton, Neyret & Holzschuch 2010): a cascade whose
// waves are shorter than two of this pixel's footprints would alias (the far sea sparkles),
// so the normal keeps only the share of each cascade's slopes the pixel resolves, and what
// it drops, with the waves shorter than every cascade, becomes the roughness of the glint:
// unresolved = Cox–Munk's σ² − Σ (share · σ_c)². The share is the part of the cascade's band,
// in ln k, whose waves span two footprints (src/sim/optics/resolvedSlopes.ts resolvedShare):
// a k⁻³ tail holds equal slope variance per e-fold of k. The foam keeps the whole Jacobian.
vec4 fftPixelDerivatives;
float fftPixelJxx;
float fftPixelPotential;
vec4 fftPixelSlopeDerivatives;
float fftPixelSlopeJxx;
float fftPixelUnresolvedVariance;
float fftPixelGroups;

// The breakup field at this pixel (fftReadPixelFields), evaluated per pixel rather than
// interpolated from the vertices: its second octave's cells are a few metres wide at 10 m/s,
// finer than the far bands' vertices.
float fftBreakup(vec2 p, bool near) {
  return fftPixelGroups;
}

// Seen from high above, the two shorter cascades' tiles would show in the glitter: each tile
// is one periodic pattern, and a pixel there resolves most of its waves. So where the pixel's
// footprint passes TILE_COPY_FROM (the geometry no longer shows these waves), each is read a
// second time, TILE_COPY_SHIFT of a tile away, and the two readings are blended as a rotation,
// own · cos θ + copy · sin θ, which keeps the slopes' variance (Heitz & Neyret 2018,
// "High-performance by-example noise using a histogram-preserving blending operator").
// θ turns with a field that never repeats and is uncorrelated with the groups
// (foamBreakupOther), TILE_COPY_TURN radians per unit of it, fast enough that cos θ and sin θ
// average to zero, so no share of the repeat is left (src/sim/waves/fft/tileCopies.ts).
const float TILE_COPY_FROM = 0.3;
const float TILE_COPY_FULL = 1.0;
const vec2 TILE_COPY_SHIFT = vec2(0.382, 0.618);
vec4 fftTileCopy(sampler2D map, vec2 p, float scale, vec2 offset) {
  return fftField(map, p, scale, offset + TILE_COPY_SHIFT * uFftN);
}

// The weights (cos θ, sin θ) of a tile's own reading and its copy.
vec2 fftCopyWeights(float field, float far) {
  float angle = far * TILE_COPY_TURN * field;
  return vec2(cos(angle), sin(angle));
}

vec4 fftBlendCopies(vec4 own, vec4 copy, vec2 weights) {
  return weights.x * own + weights.y * copy;
}

void fftReadPixelFields(vec2 p, bool near) {
  // The footprint's longer side: at grazing angles a pixel runs far along the view.
  float footprint = max(max(length(dFdx(p)), length(dFdy(p))), 1e-6);
  // ln(longest / 2 footprint) / ln(longest / shortest), with the cascades' logarithms from the uniforms.
  vec3 share = clamp((uFftLogLongestWave - log(2.0 * footprint)) * uFftPerLogBand, 0.0, 1.0);
  vec4 derivatives0 = fftField(uFftDerivatives0, p, uFftScale.x, fftOffset(0, near));
  vec4 derivatives1 = fftField(uFftDerivatives1, p, uFftScale.y, fftOffset(1, near));
  vec4 derivatives2 = fftField(uFftDerivatives2, p, uFftScale.z, fftOffset(2, near));
  vec4 foam0 = fftField(uFftFoam0, p, uFftScale.x, fftOffset(0, near));
  vec4 foam1 = fftField(uFftFoam1, p, uFftScale.y, fftOffset(1, near));
  vec4 foam2 = fftField(uFftFoam2, p, uFftScale.z, fftOffset(2, near));
  fftPixelPotential = foam2.r;
#ifdef OCEAN_WAVE_GROUPS
  vec2 octaves = foamBreakupOctaves(p, near);
  fftPixelGroups = foamBreakupOfOctaves(octaves);
#ifndef OCEAN_NEAR_BANDS
  float far = smoothstep(TILE_COPY_FROM, TILE_COPY_FULL, footprint);
  vec2 weights = fftCopyWeights(foamBreakupOther(octaves), far);
  derivatives1 = fftBlendCopies(derivatives1, fftTileCopy(uFftDerivatives1, p, uFftScale.y, fftOffset(1, near)), weights);
  derivatives2 = fftBlendCopies(derivatives2, fftTileCopy(uFftDerivatives2, p, uFftScale.z, fftOffset(2, near)), weights);
  foam1 = fftBlendCopies(foam1, fftTileCopy(uFftFoam1, p, uFftScale.y, fftOffset(1, near)), weights);
  vec4 foam2Copy = fftTileCopy(uFftFoam2, p, uFftScale.z, fftOffset(2, near));
  foam2.b = fftBlendCopies(foam2, foam2Copy, weights).b;
  // The foam left behind lives on the smallest tile too, and is never negative, so it cannot
  // be turned: its two readings are mixed by the weights' squares, which add to one.
  fftPixelPotential = mix(fftPixelPotential, foam2Copy.r, weights.y * weights.y);
#endif
#else
  fftPixelGroups = 0.0;
#endif
  fftPixelDerivatives = derivatives0 + derivatives1 + derivatives2;
  fftPixelJxx = foam0.b + foam1.b + foam2.b;
  fftPixelSlopeDerivatives = share.x * derivatives0 + share.y * derivatives1 + share.z * derivatives2;
  fftPixelSlopeJxx = dot(share, vec3(foam0.b, foam1.b, foam2.b));
  fftPixelUnresolvedVariance = max(SUN_DISC_SLOPE_VARIANCE, uSeaSlopeVariance - dot(share * share, uFftSlopeVariance));
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

float fftFoamPotential(vec2 p, bool near) {
  return fftPixelPotential;
}

vec4 fftDisplacementFields(vec2 p, bool near) {
  return fftCascadeSum(uFftDisplacement0, uFftDisplacement1, uFftDisplacement2, p, near);
}

// The slopes this pixel resolves, for its normal (see fftReadPixelFields).
vec4 fftSlopeDerivativeFields(vec2 p, bool near) {
  return fftPixelSlopeDerivatives;
}

float fftSlopeJxx(vec2 p, bool near) {
  return fftPixelSlopeJxx;
}

float waveUnresolvedSlopeVariance() {
  return fftPixelUnresolvedVariance;
}

// 1 − J of the whole sea's choppy map at this pixel, clamped to [0, 1].
float wavePinch() {
  vec4 d = fftPixelDerivatives;
  return clamp(-((1.0 + fftPixelJxx) * (1.0 + d.z) - d.w * d.w - 1.0), 0.0, 1.0);
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

float fftBreakup(vec2 p, bool near) {
  return foamBreakup(p, near);
}

// ∂Dx/∂x of the whole sea at a grid point.
float fftJxx(vec2 p, bool near) {
  return fftDisplacementFields(p, near).w;
}

// The smallest cascade's remembered foam potential at a grid point.
float fftFoamPotential(vec2 p, bool near) {
  return fftField(uFftFoam2, p, uFftScale.z, fftOffset(2, near)).r;
}

// A vertex has no footprint: its normal keeps every slope.
vec4 fftSlopeDerivativeFields(vec2 p, bool near) {
  return fftDerivativeFields(p, near);
}

float fftSlopeJxx(vec2 p, bool near) {
  return fftJxx(p, near);
}
#endif

vec3 waveDisplacement(vec2 gridXZ) {
  return fftDisplacementFields(gridXZ, false).xyz;
}

// Normal of P(x, z) = (x + Dx, h, z + Dz): ∂P/∂z × ∂P/∂x with every derivative exact from the
// spectrum (i k h, −λ k k̂ h), as FftOcean.normalAt.
vec3 fftNormal(vec2 p, bool near) {
  float jxx = fftSlopeJxx(p, near);
  vec4 d = fftSlopeDerivativeFields(p, near);
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

// Foam in two layers (docs/light-foam.md, "What the code does, and where"). Breaking now: where the whole sea's breaking measure,
// min(det J, λ_min J) (shaders/waves/fftBreaking.glsl), shifted by the breakup field that keeps
// the whitecaps off the tiles' lattice (shaders/foam/foamBreakup.glsl), is below the threshold
// that marks Monahan's share of the sea for this wind: white (0.6 thick) at the threshold, solid
// 0.45σ below it, thinning to nothing 0.55σ above it, so the whitecap's edge is a band of
// thinning lace outside the white (shaders/foam/foamMaterial.glsl).
// Left behind: what the smallest cascade remembers (shaders/fftFoamMemory.frag), a potential
// fading as e^{−t/τ} in simulation time, thin foam (a lace, shaders/foam/foamMaterial.glsl)
// thinning out as it fades, only where the breakup field lets the group's foam lie, or in a
// strong wind where the windrows sweep it, in streaks along the wind (shaders/foam/foamWindrows.glsl). Seen
// from 150 m above, the picture's white share is within 30 % of Monahan's coverage at 10, 15
// and 20 m/s (tests/browser/light/foam.test.ts).
const float FOAM_KEPT_THICKNESS = 0.7;
float fftFoamAt(vec2 p, bool near) {
  float jxx = fftJxx(p, near);
  vec4 d = fftDerivativeFields(p, near);
  float breakup = fftBreakup(p, near);
  float measure = fftBreaking(jxx, d.z, d.w) + uFoamBreakupStrength * breakup;
  float now = smoothstep(uFoamThreshold + 2.25 * uFoamSoftness, uFoamThreshold - 1.75 * uFoamSoftness, measure);
  float potential = fftFoamPotential(p, near);
  float kept = FOAM_KEPT_THICKNESS * smoothstep(0.5, 2.5, potential) * foamWindrowShare(p, near, foamGroupShare(breakup));
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
