// Thin sunlit crests glow green when the sun is behind them (OCEAN_SUBSURFACE): sunlight that
// enters the back of a crest and is scattered forward, by particles, towards the eye. The
// single-scattering derivation, its coefficients and their sources are in
// src/sim/optics/subsurfaceGlow.ts: SUBSURFACE_SCATTER is b_p d e^{−(a + b_p) d} at red, green
// and blue, the phase function Henyey–Greenstein with the particles' mean cosine g, written
// A / (B − C cos θ)^{3/2} with HENYEY_GREENSTEIN = (A, B, C) = ((1 − g²)/4π, 1 + g², 2g). How much of
// the pixel is such a crest follows the real-time forms: high above the mean level (Atlas,
// Mihelich & Tcheblokov 2019; 2Retr0/GodotOceanWaves), pinched (Crest's OceanEmission), and
// its visible face turned from the sun (Atlas's (½ − ½ n·l)³).
uniform float uCrestHeight;  // the model's typical crest height, m: a sixth of its largest, about σ (OceanMaterial)

// How pinched the crest is, 0 to 1: (1 − J) / PINCH_FULL where the model knows the Jacobian
// of its choppy map (WAVE_PINCH: the FFT sea). Elsewhere (the seed's sines, Gerstner's
// trochoids) the crest is known by its height alone: a curvature from the pixel's neighbours
// (screen-space derivatives of the normal) is constant over each triangle where the normals
// are the vertices' (the seed), and drew the glow in facets.
const float PINCH_FULL = 0.3;
float crestPinch() {
#ifdef WAVE_PINCH
  return clamp(wavePinch() / PINCH_FULL, 0.0, 1.0);
#else
  return clamp(vRelativePosition.y / uCrestHeight, 0.0, 1.0);
#endif
}

// The glow leaving the surface at this pixel (height vRelativePosition.y, normal n), towards
// the eye v, before its Fresnel transmission out of the water, which the caller applies.
vec3 subsurfaceGlow(vec3 n, vec3 v) {
  float crest = crestPinch() * (0.5 + 0.5 * clamp(vRelativePosition.y / uCrestHeight, 0.0, 1.0));
  float back = 0.5 - 0.5 * dot(n, uSunDirection);
  // The angle between the sun's ray and the line of sight inside the water, narrowed by
  // refraction to θ/n: 1 − cos(θ/n) ≈ (1 − cos θ)/n², exact where the forward lobe is (2 % off at 40°, 4 % at 60°).
  float cosInWater = 1.0 - (1.0 - dot(-v, uSunDirection)) / (WATER_IOR * WATER_IOR);
  float denominator = HENYEY_GREENSTEIN.y - HENYEY_GREENSTEIN.z * cosInWater;
  float phase = HENYEY_GREENSTEIN.x / (denominator * sqrt(denominator));
  return uSunColor * SUN_IRRADIANCE * SUBSURFACE_SCATTER * phase * crest * back * back * back * step(0.0, uSunDirection.y);
}
