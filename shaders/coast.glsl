// The coast (OCEAN_COAST; src/render/coast/coastChunk.ts puts the #defines of
// src/sim/coast/bathymetry.ts, src/sim/coast/shallowWaterColor.ts and the breaker index before this text).
// Three things the open sea does not have:
// - the sea floor's depth h(x, z), the same formula as seaDepth on the CPU;
// - the swell from far away that feels that floor: four components of its spectrum
//   (src/sim/coast/swellSpectrum.ts), each a precomputed field of unwrapped phase S_m and
//   amplitude A_m, summed as Z = Σ A_m e^{i(S_m − ω_m t + φ_m)} and limited where the envelope
//   2|Z| exceeds γ h, as coastSwellAt does on the CPU (src/sim/coast/coastSwellSlope.ts);
// - the wind sea (the wave model's own waves) calmed where the water is too shallow to hold
//   them (src/sim/coast/windSeaDamping.ts).

#include <oceano_constants>

// Two layers stacked in v (rows 0..N−1, then N..2N−1), each texel (S_a, A_a, S_b, A_b): the
// phase (rad) and amplitude (m) of two components, layer 0 components 0 and 1, layer 1
// components 2 and 3. A float texture is read with texelFetch and interpolated here, since
// linear filtering of float textures is an extension WebGL2 does not promise.
uniform highp sampler2D uCoastField;
// World x, z of texel (0, 0)'s centre, metres between texel centres, texels per side.
uniform vec4 uCoastGrid;
// Per component, ω_m (t mod T_m) − φ_m: its phase advance, reduced on the CPU so float32 keeps it exact.
uniform vec4 uCoastAdvance;
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

// ∇h at world (x, z) (seaDepthGradient): the plane's slope between the land's top and the offshore depth, else 0.
vec2 coastSeaDepthGradient(vec2 xz) {
  bool beach = uCoastFloor.x < 1.5;
  vec2 fromCentre = xz - COAST_ISLAND_CENTER;
  float r = length(fromCentre);
  float seaward = beach ? COAST_BEACH_SHORE_X - xz.x : r - COAST_ISLAND_RADIUS;
  float land = beach ? COAST_DUNE_HEIGHT : COAST_ISLAND_HEIGHT;
  float depth = seaward * uCoastFloor.y;
  if (depth <= -land || depth >= COAST_OFFSHORE_DEPTH || (!beach && r == 0.0)) return vec2(0.0);
  return beach ? vec2(-uCoastFloor.y, 0.0) : uCoastFloor.y * fromCentre / r;
}

// How much of the wind sea stays at world (x, z): min(1, γ h / H), 0 on land or with the wind sea off.
float coastWindFactor(vec2 xz) {
  return uCoastWind.x * clamp(uCoastWind.y * coastSeaDepth(xz), 0.0, 1.0);
}

vec4 coastTexel(int i, int j, int layer) {
  return texelFetch(uCoastField, ivec2(i, j + layer * int(uCoastGrid.w + 0.5)), 0);
}

// One layer at texel-index coordinates (u, v) inside [0, N − 1]²: bilinear between texel
// centres, with its rates of change along u and v (per texel) within the cell.
vec4 coastBilinear(vec2 uv, int layer, out vec4 alongU, out vec4 alongV) {
  int last = int(uCoastGrid.w + 0.5) - 1;
  int i0 = min(int(floor(uv.x)), last - 1);
  int j0 = min(int(floor(uv.y)), last - 1);
  float fu = uv.x - float(i0);
  float fv = uv.y - float(j0);
  vec4 t00 = coastTexel(i0, j0, layer);
  vec4 t10 = coastTexel(i0 + 1, j0, layer);
  vec4 t01 = coastTexel(i0, j0 + 1, layer);
  vec4 t11 = coastTexel(i0 + 1, j0 + 1, layer);
  vec4 bottom = t00 * (1.0 - fu) + t10 * fu;
  vec4 top = t01 * (1.0 - fu) + t11 * fu;
  alongU = (t10 - t00) * (1.0 - fv) + (t11 - t01) * fv;
  alongV = top - bottom;
  return bottom * (1.0 - fv) + top * fv;
}

// The layer read: two components' (S, A, S, A) at world (x, z) (componentAt,
// src/sim/coast/coastSwellSlope.ts), with their rates per metre along x (`alongX`) and z
// (`alongZ`). Outside the grid, the edge's amplitudes, and phases that go on growing at the
// edge cell's rate: the bilinear field is linear across a cell, so that rate is the difference
// between the edge texel and its inward neighbour, and no second read is needed.
vec4 coastLayerAt(vec2 xz, int layer, out vec4 alongX, out vec4 alongZ) {
  const vec4 PHASES = vec4(1.0, 0.0, 1.0, 0.0);
  float last = uCoastGrid.w - 1.0;
  vec2 uv = (xz - uCoastGrid.xy) / uCoastGrid.z;
  vec2 c = clamp(uv, 0.0, last);
  vec4 alongU;
  vec4 alongV;
  vec4 s = coastBilinear(c, layer, alongU, alongV);
  // Clamped, the field stands still along that axis but for the phases' growth.
  if (uv.x != c.x) {
    alongU *= PHASES;
    s += alongU * (uv.x - c.x);
  }
  if (uv.y != c.y) {
    alongV *= PHASES;
    s += alongV * (uv.y - c.y);
  }
  alongX = alongU / uCoastGrid.z;
  alongZ = alongV / uCoastGrid.z;
  return s;
}

// The complex sum Z = Σ A e^{iθ}, θ = S − advance, and its gradient, for the two components of
// one layer read (`s`, `alongX`, `alongZ`), added into `z` (Re Z, Im Z) and `gradient`
// (∂Re Z/∂x, ∂Im Z/∂x, ∂Re Z/∂z, ∂Im Z/∂z): ∇(A e^{iθ}) = (∇A + i A ∇S) e^{iθ}.
// `phases` gathers Σ A θ, Σ A and Σ θ for the carrier's mean phase.
void coastComponentSum(vec4 s, vec4 alongX, vec4 alongZ, vec2 advance, inout vec2 z, inout vec4 gradient, inout vec3 phases) {
  for (int m = 0; m < 2; m++) {
    vec2 phaseAmplitude = m == 0 ? s.xy : s.zw;
    vec2 rateX = m == 0 ? alongX.xy : alongX.zw;
    vec2 rateZ = m == 0 ? alongZ.xy : alongZ.zw;
    float theta = phaseAmplitude.x - advance[m];
    float c = cos(theta);
    float n = sin(theta);
    float a = phaseAmplitude.y;
    z += a * vec2(c, n);
    gradient.xy += vec2(rateX.y * c - a * rateX.x * n, rateX.y * n + a * rateX.x * c);
    gradient.zw += vec2(rateZ.y * c - a * rateZ.x * n, rateZ.y * n + a * rateZ.x * c);
    phases += vec3(a * theta, a, theta);
  }
}

// The swell at a point: its height, slope, breaking fraction now, and the carrier's phase
// arg Z = meanPhase + arg(relative) in two parts (see coastEnvelopeLimit).
struct CoastSwell {
  float height;
  vec2 slope;
  float breaking;
  float meanPhase;
  vec2 relative;
};

// The envelope limit: a narrow-band sea's wave height is H = 2|Z|; where H > γ h the sum is
// scaled by s = γ h / H, and ∇η = s ∇Re Z + Re Z ∇s, ∇s = s (∇h / h − ∇|Z| / |Z|).
// The carrier's phase arg Z is kept in two parts that interpolate between vertices without
// wrapping: the components' amplitude-weighted mean phase θ̄ (unwrapped, smooth as the phases S
// are) and the unit vector Z e^{−iθ̄} / |Z|, which turns only on the scale of a group.
CoastSwell coastEnvelopeLimit(vec2 xz, vec2 z, vec4 gradient, vec3 phases) {
  float depth = coastSeaDepth(xz);
  float modulus = length(z);
  float height = 2.0 * modulus;
  float limit = COAST_BREAKER_INDEX * max(depth, 0.0);
  float scale = 1.0;
  vec2 scaleSlope = vec2(0.0);
  if (height > limit) {
    scale = limit / height;
    if (depth > 0.0) {
      vec2 modulusSlope = vec2(dot(z, gradient.xy), dot(z, gradient.zw)) / modulus;
      scaleSlope = scale * (coastSeaDepthGradient(xz) / depth - modulusSlope / modulus);
    }
  }
  CoastSwell swell;
  swell.height = scale * z.x;
  swell.slope = scale * gradient.xz + z.x * scaleSlope;
  // breakingFraction (src/sim/coast/waveTransformation.ts): smoothstep of H / (γ h) from 0.9 to 1; on land, 1 where any wave is left.
  swell.breaking = depth <= 0.0 ? (height > 0.0 ? 1.0 : 0.0) : smoothstep(0.9, 1.0, height / limit);
  float mean = phases.y > 0.0 ? phases.x / phases.y : phases.z / 4.0;
  vec2 relative = vec2(z.x * cos(mean) + z.y * sin(mean), z.y * cos(mean) - z.x * sin(mean));
  swell.meanPhase = mean;
  swell.relative = modulus > 0.0 ? relative / modulus : vec2(1.0, 0.0);
  return swell;
}

// The swell at world (x, z): both layers read, their four components summed, the envelope limited.
CoastSwell coastSwellAt(vec2 xz) {
  vec2 z = vec2(0.0);
  vec4 gradient = vec4(0.0);
  vec3 phases = vec3(0.0);
  for (int layer = 0; layer < 2; layer++) {
    vec4 alongX;
    vec4 alongZ;
    vec4 s = coastLayerAt(xz, layer, alongX, alongZ);
    coastComponentSum(s, alongX, alongZ, layer == 0 ? uCoastAdvance.xy : uCoastAdvance.zw, z, gradient, phases);
  }
  return coastEnvelopeLimit(xz, z, gradient, phases);
}

// The wind sea's normal `n` with its slopes scaled by `factor`, tilted by the swell's `slope`.
vec3 coastTiltNormal(vec3 n, float factor, vec2 slope) {
  vec2 wind = -n.xz / max(n.y, 1e-4) * factor;
  return normalize(vec3(-(wind.x + slope.x), 1.0, -(wind.y + slope.y)));
}

// From ocean.vert: the depth, breaking fraction and the carrier's mean phase for the shallows'
// colour and the surf, the carrier's relative turn (Z e^{−iθ̄} / |Z|), and the swell's slope
// with the wind sea's factor, for a model whose normals are per pixel.
varying vec3 vCoastLook;
varying vec2 vCoastCarrier;
varying vec3 vCoastTilt;

#ifdef WAVE_VERTEX_STAGE
// The ocean's vertex: the model's displacement `d` of grid point `grid` (none with the wind sea
// off) is scaled by the depth's limit at that grid point, sideways too, so the calmed water
// neither rises nor swims; the swell is added at the point it lands on, as the wake takes it
// and as the CPU twin adds them (src/sim/coast/coastSurface.ts); `normal` is tilted alike.
// `fade`: the far rings' fade of the waves.
void coastDisplace(inout vec3 d, inout vec3 normal, vec2 grid, float fade, bool flatNormals) {
  float windFactor = coastWindFactor(grid);
  d *= windFactor;
  vec2 at = grid + d.xz;
  CoastSwell swell = coastSwellAt(at);
  d.y += swell.height * fade;
  vec2 slope = swell.slope * fade;
  if (!flatNormals) normal = coastTiltNormal(normal, windFactor, slope);
  vCoastLook = vec3(coastSeaDepth(at), swell.breaking, swell.meanPhase);
  vCoastCarrier = swell.relative;
  vCoastTilt = vec3(slope, windFactor);
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

// The surf's foam: where the swell breaks now, on the front of each crest (the bore that runs
// ahead of it) fading behind it, and a thin sheet of what earlier crests left.
// An artistic shape over a physical place: the breaking fraction decides where, the carrier's phase when.
float coastSurfFoam(vec3 look, vec2 carrier) {
  float breaking = clamp(look.y, 0.0, 1.0);
  if (breaking <= 0.0) return 0.0;
  // 1 just ahead of the crest (the carrier's phase arg Z slightly past 0), falling off over half a wavelength.
  float phase = look.z + atan(carrier.y, carrier.x);
  float front = pow(0.5 + 0.5 * cos(phase - 0.6), 10.0);
  return breaking * clamp(0.08 + 0.9 * front, 0.0, 1.0);
}
