// The seed's waves as a wave-model chunk (`#include <oceano_waves>` resolves here when
// waves=seed; see src/render/waves/). M(x, z), the ocean's displacement: the GLSL twin
// of src/sim/waves/seed/seedSurface.ts and src/sim/waves/seed/seedWaveModel.ts. Every phase and offset arrives already
// reduced (see surfaceStateAt), so float32 stays exact far from the origin and late in time.
// Keep the files in step: a parity test compares them.
//
// The contract every model's chunk meets:
//   vec3 waveDisplacement(vec2 gridXZ)  where the undisplaced grid point goes, (dx, dy, dz)
//   vec3 waveNormal(vec2 gridXZ)        unit normal of the displaced surface there
//   float waveLensHeight(vec2 worldXZ)  the short waves' height, whose bumps focus sunlight
//                                       into the underwater shafts (god rays)
//   float waveUnresolvedSlopeVariance()  the slopes the normals leave out: the glint's and the
//                                       sky reflection's roughness (ocean.frag)

#include <oceano_tiled_heightmap>

uniform float uSwellAmplitude;
uniform float uSwellFrequency;
uniform vec4 uSwellPhase;
uniform float uRippleStrength;
uniform float uRippleBlend;
uniform vec4 uRippleOffset;
uniform float uTileSize;
uniform float uHeightmapSize;
uniform float uNormalDelta;
uniform sampler2D uHeightmap0;
uniform sampler2D uHeightmap1;

const float SECOND_SWELL_AMPLITUDE = 0.45;
const float SECOND_SWELL_FREQUENCY = 1.73;
const vec2 SECOND_SWELL_DIRECTION = vec2(0.8, 0.6);

#include <oceano_sin_turns>

// The swell's angles are counted in turns and taken mod 1 before any trigonometry: the
// argument k x reaches hundreds of radians far out (sinTurns.glsl says why that matters).
float swellTurns(float cyclesPerMetre, float x, float phase) {
  return fract(cyclesPerMetre * x) + phase / TURN_RADIANS;
}

float swellHeight(vec2 p) {
  float c1 = uSwellFrequency / TURN_RADIANS;
  float first = sinTurns(swellTurns(c1, p.x, uSwellPhase.x)) * cosTurns(swellTurns(c1, p.y, uSwellPhase.y));
  float c2 = c1 * SECOND_SWELL_FREQUENCY;
  float u = SECOND_SWELL_DIRECTION.x * p.x + SECOND_SWELL_DIRECTION.y * p.y;
  float v = -SECOND_SWELL_DIRECTION.y * p.x + SECOND_SWELL_DIRECTION.x * p.y;
  float second = sinTurns(swellTurns(c2, u, uSwellPhase.z)) * cosTurns(swellTurns(c2, v, uSwellPhase.w));
  return uSwellAmplitude * (first + SECOND_SWELL_AMPLITUDE * second);
}

float sampleHeightmap(sampler2D map, vec2 p, vec2 offset) {
  return sampleTiledHeightmap(map, p, offset, uTileSize, uHeightmapSize);
}

float rippleHeight(vec2 p) {
  float a = sampleHeightmap(uHeightmap0, p, uRippleOffset.xy);
  float b = sampleHeightmap(uHeightmap1, p, uRippleOffset.zw);
  return uRippleStrength * mix(a, b, uRippleBlend);
}

float oceanHeight(vec2 p) {
  return swellHeight(p) + rippleHeight(p);
}

// The seed's fabricated neighbours: V2 = M(x + d, z), V3 = M(x, z + d); the normal is
// (V3 - V1) x (V2 - V1), written out.
vec3 oceanNormal(vec2 p, float h1) {
  float d = uNormalDelta;
  float h2 = oceanHeight(p + vec2(d, 0.0));
  float h3 = oceanHeight(p + vec2(0.0, d));
  return normalize(vec3(-(h2 - h1) * d, d * d, -(h3 - h1) * d));
}

// The height waveDisplacement last computed, and where: the vertex shader asks for the
// normal at the same point next, and the normal's first sample is that very height. Kept
// here because the shader compiler does not merge two calls that read textures, and one
// full evaluation of M in four is a quarter of the vertex stage.
vec2 lastHeightPoint = vec2(3.0e38);
float lastHeight = 0.0;

// The seam. The seed only lifts points (dx = dz = 0), so a grid point is its own world point.
vec3 waveDisplacement(vec2 gridXZ) {
  lastHeightPoint = gridXZ;
  lastHeight = oceanHeight(gridXZ);
  return vec3(0.0, lastHeight, 0.0);
}

vec3 waveNormal(vec2 gridXZ) {
  return oceanNormal(gridXZ, gridXZ == lastHeightPoint ? lastHeight : oceanHeight(gridXZ));
}

// Per-pixel detail for the far bands (WAVE_DETAIL_NORMALS, see ocean.frag): the same
// fabricated normal the vertices get, evaluated at the pixel's own point. Where the band's
// vertices lie farther apart than the ripples are long, the interpolated vertex normal
// has lost them; this puts them back.
#define WAVE_DETAIL_NORMALS
vec3 waveDetailNormal(vec2 p) {
  return oceanNormal(p, oceanHeight(p));
}

// The sun's glint and the sky's reflection take what this sea's normals do not show as
// roughness (ocean.frag): Cox & Munk's σ² for the wind less the swell's and ripples' own,
// set per frame (src/sim/waves/seed/seedSlopes.ts). The normals show those slopes at every
// distance (the vertices' fabricated normals, a metre's difference quotient), so the
// roughness is one number for the whole sea.
uniform float uSlopeRoughness;

float waveUnresolvedSlopeVariance() {
  return uSlopeRoughness;
}

// The ripples alone: the swell is too long to focus light within the shafts' few metres.
float waveLensHeight(vec2 worldXZ) {
  return rippleHeight(worldXZ);
}
