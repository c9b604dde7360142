// The interactive waves (iWave, src/render/iwave/gpuIWave.ts) added to whichever wave model is
// active: the height field's value and slope at a world point, read from the solver's texture;
// the hand-over of the boat's waves to the analytic Kelvin wake; the tint and foam of steep
// water. Compiled in only while interactiveWaves is on (OceanMaterial.setInteractiveWavesOn),
// and fetched with their code (src/render/iwave/iwaveChunk.ts puts the #defines it reads
// before it: IWAVE_HAND_OVER_WIDTH, IWAVE_TINT_FROM, IWAVE_FOAM_FROM, IWAVE_STOKES_SLOPE,
// IWAVE_TINT_STRENGTH, IWAVE_CREST_COLOR, from src/sim/iwave/).

// (h now, h one step ago) per texel; texel (i, j) stands at
// centre + ((i, j) + ½ − n/2)·Δx.
uniform sampler2D uIWaveField;
// (centre x, centre z, Δx, n): the grid's centre in world metres, a multiple of Δx (float32
// holds it exactly, so less the render origin it stays exact wherever the camera is).
uniform vec4 uIWaveGrid;
// The hand-over (src/sim/iwave/kelvinHandOver.ts): the boat's world (x, z), the distance D
// where the analytic wake takes over, and 1 while it applies (the wake drawn beside the field).
uniform vec4 uIWaveHandOver;

float iwaveTexel(ivec2 p) {
  int n = int(uIWaveGrid.w);
  if (p.x < 0 || p.y < 0 || p.x >= n || p.y >= n) return 0.0;
  return texelFetch(uIWaveField, p, 0).r;
}

// Bilinear between texel centres, as IWaveGrid.sample does.
float iwaveBilinear(vec2 texel) {
  vec2 base = floor(texel);
  vec2 f = texel - base;
  ivec2 p = ivec2(base);
  float h00 = iwaveTexel(p);
  float h10 = iwaveTexel(p + ivec2(1, 0));
  float h01 = iwaveTexel(p + ivec2(0, 1));
  float h11 = iwaveTexel(p + ivec2(1, 1));
  return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
}

// (h, ∂h/∂x, ∂h/∂z) at a point given relative to the render origin `origin`, metres. It fades
// out over the grid's outer tenth (inside the sponge), so the field's square edge never shows.
vec3 iwaveHeightAndGradient(vec2 relativeXZ, vec2 origin) {
  float spacing = uIWaveGrid.z;
  float halfWidth = 0.5 * uIWaveGrid.w * spacing;
  vec2 fromCentre = relativeXZ - (uIWaveGrid.xy - origin);
  float edge = max(abs(fromCentre.x), abs(fromCentre.y)) / halfWidth;
  float fade = 1.0 - smoothstep(0.9, 1.0, edge);
  if (fade <= 0.0) return vec3(0.0);
  vec2 texel = fromCentre / spacing + 0.5 * uIWaveGrid.w - 0.5;
  float h = iwaveBilinear(texel);
  float dx = iwaveBilinear(texel + vec2(1.0, 0.0)) - iwaveBilinear(texel - vec2(1.0, 0.0));
  float dz = iwaveBilinear(texel + vec2(0.0, 1.0)) - iwaveBilinear(texel - vec2(0.0, 1.0));
  return fade * vec3(h, dx / (2.0 * spacing), dz / (2.0 * spacing));
}

// (the analytic wake's weight, the field's) at a point relative to the render origin: the
// twin of handOverWeights in kelvinHandOver.ts. Within D of the boat the field carries its
// waves, past D + IWAVE_HAND_OVER_WIDTH the wake does; both are 1 while no hand-over applies.
vec2 iwaveHandOver(vec2 relativeXZ, vec2 origin) {
  if (uIWaveHandOver.w == 0.0) return vec2(1.0);
  float w = smoothstep(uIWaveHandOver.z, uIWaveHandOver.z + IWAVE_HAND_OVER_WIDTH, length(relativeXZ - (uIWaveHandOver.xy - origin)));
  return vec2(w, 1.0 - w);
}

// The steep water's tint and foam from the field's slope: the twins of fieldTint and fieldFoam
// in src/sim/iwave/steepnessTint.ts.
float iwaveTint(vec2 slope) {
  return IWAVE_TINT_STRENGTH * smoothstep(IWAVE_TINT_FROM, IWAVE_FOAM_FROM, length(slope));
}

vec3 iwaveTinted(vec3 water, vec2 slope) {
  return mix(water, IWAVE_CREST_COLOR, iwaveTint(slope));
}

float iwaveFoam(vec2 slope) {
  return smoothstep(IWAVE_FOAM_FROM, IWAVE_STOKES_SLOPE, length(slope));
}
