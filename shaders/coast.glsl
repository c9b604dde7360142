// The coast (OCEAN_COAST; src/render/coast/coastChunk.ts puts the #defines of
// src/sim/coast/bathymetry.ts and src/sim/coast/shallowWaterColor.ts before this text).
// Three things the open sea does not have:
// - the sea floor's depth h(x, z), the same formula as seaDepth on the CPU;
// - the swell from far away that feels that floor: a precomputed field (src/sim/coast/) of
//   unwrapped phase S, amplitude a, depth and breaking fraction, read as
//   sampleCoastField reads it on the CPU, and η = a cos(S − ω t);
// - the wind sea (the wave model's own waves) calmed where the water is too shallow to hold
//   them (src/sim/coast/windSeaDamping.ts).

#include <oceano_constants>

// Four floats per texel: S (rad), a (m), h (m), breaking fraction. A float texture is read
// with texelFetch and interpolated here, since linear filtering of float textures is an
// extension WebGL2 does not promise.
uniform highp sampler2D uCoastField;
// World x, z of texel (0, 0)'s centre, metres between texel centres, texels per side.
uniform vec4 uCoastGrid;
// ω (t mod T): the swell's phase advance, reduced on the CPU so float32 keeps it exact.
uniform float uCoastAdvance;
// x: 1 with the wind sea on, 0 off; y: γ / H, the breaker index over the wind sea's largest height.
uniform vec2 uCoastWind;
// x: the floor's shape (1 beach, 2 island); y: its slope.
uniform vec2 uCoastFloor;

// The still water's depth at world (x, z), metres, ≤ 0 on land (seaDepth in src/sim/coast/bathymetry.ts).
float coastSeaDepth(vec2 xz) {
  bool beach = uCoastFloor.x < 1.5;
  float seaward = beach ? COAST_BEACH_SHORE_X - xz.x : length(xz - COAST_ISLAND_CENTER) - COAST_ISLAND_RADIUS;
  float land = beach ? COAST_DUNE_HEIGHT : COAST_ISLAND_HEIGHT;
  return min(COAST_OFFSHORE_DEPTH, max(-land, seaward * uCoastFloor.y));
}

// How much of the wind sea stays at world (x, z): min(1, γ h / H), 0 on land or with the wind sea off.
float coastWindFactor(vec2 xz) {
  return uCoastWind.x * clamp(uCoastWind.y * coastSeaDepth(xz), 0.0, 1.0);
}

vec4 coastTexel(int i, int j) {
  return texelFetch(uCoastField, ivec2(i, j), 0);
}

// All four channels at texel-index coordinates (u, v) inside [0, N − 1]²: bilinear between
// texel centres, with their rates of change along u and v (per texel) within the cell.
vec4 coastBilinear(vec2 uv, out vec4 alongU, out vec4 alongV) {
  int last = int(uCoastGrid.w + 0.5) - 1;
  int i0 = min(int(floor(uv.x)), last - 1);
  int j0 = min(int(floor(uv.y)), last - 1);
  float fu = uv.x - float(i0);
  float fv = uv.y - float(j0);
  vec4 t00 = coastTexel(i0, j0);
  vec4 t10 = coastTexel(i0 + 1, j0);
  vec4 t01 = coastTexel(i0, j0 + 1);
  vec4 t11 = coastTexel(i0 + 1, j0 + 1);
  vec4 bottom = t00 * (1.0 - fu) + t10 * fu;
  vec4 top = t01 * (1.0 - fu) + t11 * fu;
  alongU = (t10 - t00) * (1.0 - fv) + (t11 - t01) * fv;
  alongV = top - bottom;
  return bottom * (1.0 - fv) + top * fv;
}

// The field at world (x, z) (sampleCoastField, src/sim/coast/coastFieldSampling.ts): outside the
// grid, the edge's amplitude, depth and breaking, and a phase that goes on growing at the
// edge's rate. `slope`: ∂S/∂x, ∂S/∂z, ∂a/∂x, ∂a/∂z, per metre (coastSwellSlope.ts on the CPU).
vec4 coastFieldAt(vec2 xz, out vec4 slope) {
  float last = uCoastGrid.w - 1.0;
  vec2 uv = (xz - uCoastGrid.xy) / uCoastGrid.z;
  vec2 c = clamp(uv, 0.0, last);
  vec4 alongU;
  vec4 alongV;
  vec4 s = coastBilinear(c, alongU, alongV);
  // Clamped, the field stands still along that axis but for the phase's growth.
  if (uv.x != c.x) alongU = vec4(0.0);
  if (uv.y != c.y) alongV = vec4(0.0);
  vec4 unused;
  float edge = s.x;
  if (uv.x != c.x) {
    float inward = uv.x > c.x ? -1.0 : 1.0;
    float rate = (edge - coastBilinear(vec2(c.x + inward, c.y), unused, unused).x) * -inward;
    s.x += rate * (uv.x - c.x);
    alongU.x = rate;
  }
  if (uv.y != c.y) {
    float inward = uv.y > c.y ? -1.0 : 1.0;
    float rate = (edge - coastBilinear(vec2(c.x, c.y + inward), unused, unused).x) * -inward;
    s.x += rate * (uv.y - c.y);
    alongV.x = rate;
  }
  slope = vec4(alongU.x, alongV.x, alongU.y, alongV.y) / uCoastGrid.z;
  return s;
}

// The swell's height η = a cos(S − ω t) and slope (∂η/∂x, ∂η/∂z) from a field sample and its slopes.
vec3 coastSwellOf(vec4 s, vec4 slope) {
  float phase = s.x - uCoastAdvance;
  float c = cos(phase);
  float n = sin(phase);
  return vec3(s.y * c, slope.zw * c - s.y * n * slope.xy);
}

// The wind sea's normal `n` with its slopes scaled by `factor`, tilted by the swell's `slope`.
vec3 coastTiltNormal(vec3 n, float factor, vec2 slope) {
  vec2 wind = -n.xz / max(n.y, 1e-4) * factor;
  return normalize(vec3(-(wind.x + slope.x), 1.0, -(wind.y + slope.y)));
}

// From ocean.vert: the depth, breaking and swell phase for the shallows' colour and the surf,
// and the swell's slope with the wind sea's factor, for a model whose normals are per pixel.
varying vec3 vCoastLook;
varying vec3 vCoastTilt;

#ifdef WAVE_VERTEX_STAGE
// The ocean's vertex: the model's displacement `d` of grid point `grid` (none with the wind sea
// off) becomes, at the displaced point as the wake takes it and as the CPU twin adds them
// (src/sim/coast/coastSurface.ts), the wind sea scaled by the depth's limit plus the swell;
// `normal` is tilted alike. `fade`: the far rings' fade of the waves.
void coastDisplace(inout vec3 d, inout vec3 normal, vec2 grid, float fade, bool flatNormals) {
  d *= uCoastWind.x;
  vec2 at = grid + d.xz;
  float windFactor = coastWindFactor(at);
  vec4 slope;
  vec4 field = coastFieldAt(at, slope);
  vec3 swell = coastSwellOf(field, slope) * fade;
  d.y = d.y * windFactor + swell.x;
  if (!flatNormals) normal = coastTiltNormal(normal, windFactor, swell.yz);
  // The depth, the breaking fraction and the phase S − ω t.
  vCoastLook = vec3(coastSeaDepth(at), field.w, field.x - uCoastAdvance);
  vCoastTilt = vec3(swell.yz, windFactor);
}
#endif

// The water's own colour over a bed `depth` metres down: the deep water's (`deep`, whose
// reflectance is R∞) with R∞ replaced by R(h) = R∞ + (ρ − R∞) e^(−2 K h)
// (src/sim/coast/shallowWaterColor.ts): turquoise over sand in the shallows, sand on the shore.
vec3 coastShallowWater(vec3 deep, float depth) {
  vec3 bed = exp(-2.0 * COAST_ATTENUATION * max(depth, 0.0));
  vec3 reflectance = WATER_BODY_REFLECTANCE + (COAST_BED_ALBEDO - WATER_BODY_REFLECTANCE) * bed;
  return deep * reflectance / WATER_BODY_REFLECTANCE;
}

// The surf's foam: where the field says the swell breaks, on the front of each crest (the bore
// that runs ahead of it) fading behind it, and a thin sheet of what earlier crests left.
// An artistic shape over a physical place: the breaking fraction decides where, the phase when.
float coastSurfFoam(vec3 look) {
  float breaking = clamp(look.y, 0.0, 1.0);
  if (breaking <= 0.0) return 0.0;
  // 1 just ahead of the crest (phase slightly past 0), falling off over half a wavelength.
  float front = pow(0.5 + 0.5 * cos(look.z - 0.6), 10.0);
  return breaking * clamp(0.08 + 0.9 * front, 0.0, 1.0);
}
