// M(x, z), the ocean's displacement: the GLSL twin of src/sim/surface.ts. Every phase and
// offset arrives already reduced (see surfaceStateAt), so float32 stays exact far from the
// origin and late in time. Keep the two files in step: a parity test compares them.

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

float swellHeight(vec2 p) {
  float k = uSwellFrequency;
  float first = sin(k * p.x + uSwellPhase.x) * cos(k * p.y + uSwellPhase.y);
  float k2 = k * SECOND_SWELL_FREQUENCY;
  float u = SECOND_SWELL_DIRECTION.x * p.x + SECOND_SWELL_DIRECTION.y * p.y;
  float v = -SECOND_SWELL_DIRECTION.y * p.x + SECOND_SWELL_DIRECTION.x * p.y;
  float second = sin(k2 * u + uSwellPhase.z) * cos(k2 * v + uSwellPhase.w);
  return uSwellAmplitude * (first + SECOND_SWELL_AMPLITUDE * second);
}

// Bilinear with wrap by hand: texel (i, j) sits at world offset (i, j) * tile / size.
// Each texel holds its own height and those of its +x, +z and diagonal neighbours
// (wrapped), so one fetch gives the four corners and no modulo is needed.
float sampleHeightmap(sampler2D map, vec2 p) {
  vec2 st = fract(p / uTileSize) * uHeightmapSize;
  vec2 cell = floor(st);
  vec2 f = st - cell;
  vec4 corners = texelFetch(map, ivec2(cell), 0);
  return mix(mix(corners.x, corners.y, f.x), mix(corners.z, corners.w, f.x), f.y);
}

float rippleHeight(vec2 p) {
  float a = sampleHeightmap(uHeightmap0, p + uRippleOffset.xy);
  float b = sampleHeightmap(uHeightmap1, p + uRippleOffset.zw);
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
