// Thin sunlit crests glow green when the sun is behind them (OCEAN_SUBSURFACE): sunlight that
// enters the back of a crest and is scattered forward, by particles, towards the eye. The
// single-scattering derivation, its coefficients and their sources are in
// src/sim/optics/subsurfaceGlow.ts: SUBSURFACE_SCATTER is b_p d e^{−(a + b_p) d} at red, green
// and blue, the phase function Henyey–Greenstein with the particles' mean cosine. How much of
// the pixel is such a crest follows the real-time forms: high above the mean level (Atlas,
// Mihelich & Tcheblokov 2019; 2Retr0/GodotOceanWaves), pinched (Crest's OceanEmission), and
// its visible face turned from the sun (Atlas's (½ − ½ n·l)³).
uniform float uCrestHeight;  // the model's typical crest height, m: a sixth of its largest, about σ (OceanMaterial)

float henyeyGreenstein(float cosTheta) {
  const float g = PARTICLE_MEAN_COSINE;
  return (1.0 - g * g) / (12.566371 * pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

// How pinched the crest is, 0 to 1: (1 − J) / PINCH_FULL where the model knows the Jacobian of
// its choppy map (WAVE_PINCH); otherwise the surface's curvature, the divergence of the normal
// from the pixel's neighbours (screen-space derivatives), times the crest height. A crest is
// where the surface is pinched, wherever the swell under it has carried it; a high one glows more.
const float PINCH_FULL = 0.3;
float crestPinch(vec3 n, vec2 p) {
#ifdef WAVE_PINCH
  return clamp(wavePinch() / PINCH_FULL, 0.0, 1.0);
#else
  vec2 px = dFdx(p);
  vec2 py = dFdy(p);
  vec2 nx = dFdx(n.xz);
  vec2 ny = dFdy(n.xz);
  float det = px.x * py.y - px.y * py.x;
  float divergence = (nx.x * py.y - ny.x * px.y + ny.y * px.x - nx.y * py.x) / (abs(det) > 1e-8 ? det : 1e-8);
  return clamp(divergence * uCrestHeight / PINCH_FULL, 0.0, 1.0);
#endif
}

// The glow leaving the surface at height `height` (m), normal n, towards the eye v (before its
// Fresnel transmission out of the water, which the caller applies).
vec3 subsurfaceGlow(vec3 n, vec3 v, float height, float pinch) {
  float crest = pinch * (0.5 + 0.5 * clamp(height / uCrestHeight, 0.0, 1.0));
  float backlit = pow(0.5 - 0.5 * dot(n, uSunDirection), 3.0);
  // The angle between the sun's ray and the line of sight inside the water, narrowed by refraction.
  float cosInWater = cos(acos(clamp(dot(-v, uSunDirection), -1.0, 1.0)) / WATER_IOR);
  float sunUp = step(0.0, uSunDirection.y);
  return uSunColor * SUN_IRRADIANCE * SUBSURFACE_SCATTER * henyeyGreenstein(cosInWater) * crest * backlit * sunUp;
}
