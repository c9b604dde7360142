// Water shading. From above: Fresnel-weighted mix of the reflected sky cube and the
// water's own colour, a sun highlight, and haze towards the horizon. From below: the sky
// refracted through Snell's window, total internal reflection of the water outside it.
//
// Each optional feature is one #define, set by OceanMaterial (or by the wave model's chunk,
// WAVE_…), so that a program holds only what its view draws. perf: a define rather than a
// uniform branch keeps each program small to compile and light on registers on a GPU; on a
// software rasterizer only, which runs both sides of a branch, it also saves the untaken side
// (docs/shader-notes.md).

// Tells a wave-model chunk it is compiled for the ocean's pixels (normals and foam only), where
// it may read its fields more cheaply than the vertex stage (shaders/waves/fft.glsl).
#define WAVE_FRAGMENT_STAGE
#include <oceano_water_volume>
#include <oceano_constants>
#include <oceano_waves>

#include <oceano_sky_cube>
#ifdef OCEAN_PREFILTERED_SKY
// The sky as a sea of this one roughness reflects it, blurred once for the whole sea
// (src/render/sky/prefilteredSky.ts), holding the colour's square root as the sky's cube does.
uniform samplerCube uPrefilteredSky;
#endif
uniform sampler2D uFresnelTable;
uniform sampler2D uFresnelFromBelow;
uniform bool uFresnelEnabled;
// Set while the frame goes through the underwater passes, which read the side from alpha.
uniform bool uMarkSides;
uniform vec3 uDeepColor;
uniform vec3 uFacingTint;
uniform vec3 uSunDirection;
uniform vec3 uSunColor;
#include <oceano_haze>

// The pixel's position and the eye's relative to the render origin (see ocean.vert).
varying vec3 vRelativePosition;
uniform vec3 uEyeRelative;
uniform mat4 uViewRelative;
varying vec3 vNormal;
varying float vBand;
varying vec2 vGridXZ;
varying vec2 vRelativeGridXZ;
flat varying float vVertexSpacing;
varying float vWaveFade;
uniform bool uFlatNormals;

// Foam as flat paint (the foamTexture parameter off): white, lit by sun and sky.
const vec3 FOAM_COLOR = vec3(0.82, 0.86, 0.88);

// The haze towards the horizon: its colour, the sky at the horizon beyond the pixel, and its
// weight (shaders/haze.glsl). The near bands' material (OCEAN_NEAR_BANDS: vertices
// at most a few metres apart) interpolates both from its vertices (ocean.vert): where the
// haze weighs anything a triangle spans about a degree of azimuth, too little for the sky's
// colour to bend, and the distance across it is linear to a millimetre. The far bands, rings
// and skirt, whose cells span kilometres, look both up per pixel. perf: per vertex only to
// spare a software rasterizer (docs/shader-notes.md).
#ifdef OCEAN_NEAR_BANDS
varying vec3 vHorizon;
varying float vHaze;
vec3 hazeColor(vec3 toEye) { return vHorizon; }
float hazeWeight() { return vHaze; }
#else
vec3 hazeColor(vec3 toEye) { return skyCubeColor(normalize(vec3(-toEye.x, 0.0, -toEye.z))); }
float hazeWeight() { return hazeWeightBetween(uEyeRelative, vRelativePosition); }
#endif

// The boat's wake, compiled in while it is on (OceanMaterial). Its slope and foam come
// interpolated from the vertices (its waves are 8 m and longer); a model whose normals are
// evaluated per pixel tilts them by the slope here.
varying vec2 vWakeSlope;
varying float vWakeFoam;
#ifdef OCEAN_WAKE
#include <oceano_wake>
vec3 withWakeSlope(vec3 n) { return wakeTiltNormal(n, vWakeSlope); }
float withWakeFoam(float foam) { return max(foam, vWakeFoam); }
#else
vec3 withWakeSlope(vec3 n) { return n; }
float withWakeFoam(float foam) { return foam; }
#endif
#ifdef OCEAN_COAST
#include <oceano_coast>
#endif
#ifdef OCEAN_IWAVE
// The interactive field's steep water: paler, greener where light crosses a thin crest, and
// foam as a wave nears Stokes's limit (src/sim/iwave/steepnessTint.ts, shaders/iwave.glsl).
#include <oceano_iwave>
varying vec2 vIWaveSlope;
#endif

// The sun's highlight: a narrow lobe around the direction that brings the sun to the eye, of
// the given sharpness (the cosine's power) and strength; none once the sun has set.
vec3 sunLobe(float cosFromSun, float sharpness, float strength) {
  float sunVisible = step(0.0, uSunDirection.y);
  return uSunColor * pow(max(cosFromSun, 0.0), sharpness) * strength * sunVisible;
}

// The sun's glint on a sea whose normal shows only some of its slopes (every model's chunk says
// how much it leaves out: waveUnresolvedSlopeVariance): the rest, of mean-square slope
// `variance`, are facets within the pixel, Gaussian as Cox & Munk measured them, and the glint is the microfacet BRDF
// integrated over them (Bruneton, Neyret & Holzschuch 2010, eq. 7–9; the tested twin is
// src/sim/optics/beckmannGlint.ts): E_sun F(v·h) p(tan θh) / (4 cos θv cos⁴θh (1 + Λv + Λl)).
// It widens with the wind, fades at its edges, and where a pixel covers many waves it is
// their average, not one of them picked at random.
// Smith's shadowing of Gaussian facets of mean-square slope σ² (σ²/2 in the plane of incidence),
// seen at cos θ, in Walter et al.'s rational form (2007, eq. 27; the twin is
// src/sim/optics/beckmannGlint.ts smithLambdaRational): no exponential and no erfc per pixel.
float smithLambda(float cosTheta, float variance) {
  float c = clamp(cosTheta, 1e-4, 0.999999);
  float nu = c / sqrt((1.0 - c * c) * variance);
  return nu < 1.6 ? (1.0 - 1.259 * nu + 0.396 * nu * nu) / (3.535 * nu + 2.181 * nu * nu) : 0.0;
}

// The exact Fresnel reflectance from air into water in closed form (Cook & Torrance 1982;
// the twin is src/sim/optics/fresnel.ts fresnelClosedForm): each facet's reflectance of the
// sun, at the angle between the eye and the half vector. perf: cheaper than two table reads
// on a software rasterizer (docs/light-cost.md, "What the default view's pixels pay for").
float facetFresnel(float cosIncidence) {
  float c = clamp(cosIncidence, 0.0, 1.0);
  float g = sqrt(WATER_IOR * WATER_IOR - 1.0 + c * c);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

vec3 sunGlint(vec3 n, vec3 v, float variance, float fresnel) {
  vec3 h = normalize(uSunDirection + v);
  float cosH = dot(h, n);
  float cosV = max(dot(v, n), 0.01);
  float cosL = max(dot(uSunDirection, n), 0.01);
  float tanH2 = (1.0 - cosH * cosH) / (cosH * cosH);
  float density = exp(-tanH2 / variance) / (3.14159265 * variance);
  float shadowing = 1.0 + smithLambda(cosV, variance) + smithLambda(cosL, variance);
  float sunVisible = step(0.0, uSunDirection.y) * step(0.0, cosH);
  return uSunColor * SUN_IRRADIANCE * fresnel * density / (4.0 * cosV * cosH * cosH * cosH * cosH * shadowing) * sunVisible;
}

// The glint is the sun's own radiance, many times the sky's: a display shows it only through a
// tone curve. The app's renderer runs one over the whole frame (shaders/highlightRollOff.glsl);
// in a scene of yours whose renderer has none (NoToneMapping), the sea rolls its own highlights
// off (OCEAN_OWN_ROLL_OFF) rather than clip them, and in one with a curve of its own it leaves
// them to that curve.
#ifdef OCEAN_OWN_ROLL_OFF
#include <oceano_highlight_roll_off>
#endif

#include <oceano_fresnel_lookup>

// The water's own colour from its optics (shaders/waterBody.glsl): the same at every point, so
// worked out once a vertex, not once a pixel (perf: vertices are far fewer than pixels on any
// machine; docs/light-cost.md).
#ifdef OCEAN_WATER_OPTICS
flat varying vec3 vWaterBody;
#endif

#ifdef OCEAN_SUBSURFACE
#include <oceano_subsurface>
#endif

// Foam drawn as foam (shaders/foam/foamMaterial.glsl), while its detail texture is there and
// the foamTexture parameter is on; otherwise flat white paint, for the lesson that shows both.
#ifdef OCEAN_FOAM_TEXTURE
#include <oceano_foam>
#endif

// The underside's shading, called only while the view may be under the water
// (OCEAN_SEEN_FROM_BELOW, set by OceanMaterial.setSeenFromBelow; otherwise only front faces
// are drawn, and the compiler drops the uncalled function).
const float WATER_OVER_AIR = WATER_IOR;

// v points from the surface down to the eye; n is the surface normal (facing the air).
vec3 shadeFromBelow(vec3 v, vec3 n) {
  vec3 towardsWater = -n;
  float cosIncidence = max(dot(towardsWater, v), 0.0);
  vec3 up = refract(-v, towardsWater, WATER_OVER_AIR);
  bool totalReflection = dot(up, up) == 0.0;
  // Without Fresnel the window still ends where Snell's law says: inside it, all sky.
  float reflectance = uFresnelEnabled ? fresnelLookup(uFresnelFromBelow, cosIncidence) : (totalReflection ? 1.0 : 0.0);

  vec3 through = vec3(0.0);
  if (!totalReflection) {
    vec3 t = normalize(up);
    through = skyCubeColor(t) + sunLobe(dot(t, uSunDirection), 700.0, 30.0);
  }
  vec3 down = reflect(-v, towardsWater);
  vec3 mirrored = waterVolumeColor(down);
#ifdef OCEAN_COAST
  // Over a shallow bed the mirror shows the bed, through twice the water of the shallows' colour
  // from above (which counts h down and h back): h down to it, and back along the mirrored ray.
  float depth = max(vCoastLook.x, 0.0);
  mirrored = coastShallowWater(mirrored, depth + depth / max(-down.y, 0.1));
#endif
  return mix(through, mirrored, reflectance);
}

void main() {
  vec3 toEye = uEyeRelative - vRelativePosition;
  float distance = length(toEye);
  vec3 v = toEye / distance;
  vec3 n = normalize(vNormal);
#ifdef WAVE_PIXEL_NORMALS
  // The model's per-pixel fields, read once here, outside every branch (shaders/waves/fft.glsl).
  wavePixelFields(vRelativeGridXZ, true);
  // Exact normals (spectral slopes, or the Gerstner sum's closed form) at this pixel's own
  // grid point, not interpolated between vertices: the mapping from grid to displaced
  // surface is smooth, so interpolating the grid point is exact to first order.
  // The teaching view OCEAN_NORMALS_COMPARE keeps the vertices' fabricated normals (from
  // ocean.vert) on the right half of the screen.
#ifdef OCEAN_NORMALS_COMPARE
  bool fabricatedHalf = (uViewRelative * vec4(vRelativePosition, 1.0)).x > 0.0;
#else
  const bool fabricatedHalf = false;
#endif
  if (!uFlatNormals && !fabricatedHalf) {
    // At the grid point relative to the render origin: exact 10⁶ m out, where vGridXZ moves in 6 cm steps.
    n = waveNormalNear(vRelativeGridXZ);
    n = withWakeSlope(n);
#ifdef OCEAN_COAST
    n = coastTiltNormal(n, vCoastTilt.z, vCoastTilt.xy);
#endif
  }
#endif
  // Detail normals: a model whose normals are per vertex loses its short waves where the
  // band's vertices are farther apart than they are long (48 m in band 5, the ripples are a
  // few metres): the far sea goes flat. There the normal is evaluated per pixel instead,
  // faded in as the vertex spacing grows past DETAIL_FROM (flat per chunk, so exactly 0 below
  // it) and out again as the pixel's footprint on the sea grows past the ripples' length,
  // where the detail could only alias (a normal map would need mipmapped slopes there).
  // Near the camera, and in the default view (whose far bands are seen at grazing angles,
  // footprints of tens of metres), the weight is 0 and the picture is unchanged.
  // Band 2 (6 m) keeps its vertex normals, band 3 (12 m) and coarser get the full detail.
  // perf: left out of the programs where the weight is 0 or hardly shows: the near bands'
  // (OCEAN_NEAR_BANDS) and the view from wholly under the water (OCEAN_ONLY_FROM_BELOW), whose
  // far bands lie at grazing angles behind the fog, outside Snell's window (docs/shader-notes.md).
#if defined(WAVE_DETAIL_NORMALS) && !defined(OCEAN_NEAR_BANDS) && !defined(OCEAN_ONLY_FROM_BELOW)
  const float DETAIL_FROM = DETAIL_NORMALS_FROM;
  const float DETAIL_FULL = 12.0;
  const float FOOTPRINT_FULL = 1.0;
  const float FOOTPRINT_NONE = 2.0;
  const float LONGEST_FULL = 2.0;
  const float LONGEST_NONE = 4.0;
  if (!uFlatNormals) {
    // The square root of the pixel's area on the sea: at grazing angles a pixel is long
    // along the view and narrow across it, and the ripples show across.
    // Along the view the pixel may still not exceed the longest ripples' half wavelength.
    float across = length(dFdx(vGridXZ));
    float along = length(dFdy(vGridXZ));
    float footprint = sqrt(across * along);
    float weight = smoothstep(DETAIL_FROM, DETAIL_FULL, vVertexSpacing) * (1.0 - smoothstep(FOOTPRINT_FULL, FOOTPRINT_NONE, footprint))
      * (1.0 - smoothstep(LONGEST_FULL, LONGEST_NONE, max(across, along)));
    if (weight > 0.0) {
      vec3 detail = normalize(mix(vec3(0.0, 1.0, 0.0), waveDetailNormal(vGridXZ), vWaveFade));
#ifdef OCEAN_COAST
      // The detail is the wind sea's too: calmed by the depth and tilted by the swell, as the vertex's normal is.
      detail = coastTiltNormal(detail, vCoastTilt.z, vCoastTilt.xy);
#endif
      n = normalize(mix(n, detail, weight));
    }
  }
#endif
#ifdef OCEAN_SHOW_NORMALS
  // The teaching view of the normal itself as a colour, (n + 1) / 2, written without tone mapping.
  gl_FragColor = vec4(n * 0.5 + 0.5, 1.0);
  return;
#endif
  // With uMarkSides, alpha tells the underwater pass which side of this very mesh the line
  // of sight came from: 0.5 from below, 0 from above. Drawn straight to the canvas it is 1.
#ifdef OCEAN_ONLY_FROM_BELOW
  // The whole view is under the water (OceanMaterial.setSeenFromBelow('below')): a line of
  // sight from an eye in the water meets the surface from below first, so only back faces
  // are drawn and the shading from above is left out of the program below.
  gl_FragColor = vec4(shadeFromBelow(v, n), uMarkSides ? 0.5 : 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
#else
#ifdef OCEAN_SEEN_FROM_BELOW
  if (!gl_FrontFacing) {
    gl_FragColor = vec4(shadeFromBelow(v, n), uMarkSides ? 0.5 : 1.0);
    #include <tonemapping_fragment>
    #include <colorspace_fragment>
    #include <oceano_scene_encode>
    return;
  }
#endif
  // The slopes the normal does not show, Cox & Munk's σ² less what the model resolves here:
  // they blur the sky's reflection and spread the sun's glint alike. A lesson of a windless
  // mirror (seaRoughness off) keeps only the sun's disc.
#ifdef OCEAN_SMOOTH_SEA
  float roughness = SUN_DISC_SLOPE_VARIANCE;
#else
  float roughness = waveUnresolvedSlopeVariance();
#endif
  float cosIncidence = max(dot(n, v), 0.0);

  float reflectance = uFresnelEnabled ? fresnelLookup(uFresnelTable, cosIncidence) : 0.5;

  vec3 r = reflect(-v, n);
  // A reflected ray that points below the horizon would see the sea, not the sky.
  r.y = max(r.y, 0.0);
  // The sky blurred by the roughness below the pixel (above), unless a lesson asks for it sharp
  // (skyBlur off); where that roughness is the same everywhere, blurred once for the whole sea.
#if defined(OCEAN_SHARP_SKY)
  vec3 sky = skyCubeColor(r);
#elif defined(OCEAN_PREFILTERED_SKY)
  vec3 stored = textureLod(uPrefilteredSky, r, 0.0).rgb;
  vec3 sky = stored * stored;
#else
  vec3 sky = skyCubeColorRough(r, roughness);
#endif

#ifdef OCEAN_WATER_OPTICS
  vec3 water = vWaterBody;
#ifdef OCEAN_COAST
  water = coastShallowWater(water, vCoastLook.x);
#endif
#else
  vec3 water = mix(uDeepColor, uFacingTint, cosIncidence * cosIncidence);
#endif
#ifdef OCEAN_IWAVE
  water = iwaveTinted(water, vIWaveSlope);
#endif
  vec3 color = mix(water, sky, reflectance);
#ifdef OCEAN_SUBSURFACE
  // Sunlight through thin crests (shaders/subsurface.glsl), leaving through the surface as the water's own colour does.
  color += (1.0 - reflectance) * subsurfaceGlow(n, v);
#endif

  vec3 halfway = normalize(uSunDirection + v);
  // Each facet reflects the sun by its own Fresnel, at the angle between the eye and the half vector.
  float facetReflectance = uFresnelEnabled ? facetFresnel(dot(v, halfway)) : 0.5;
  color += sunGlint(n, v, roughness, facetReflectance);

  float foam = 0.0;
#ifdef WAVE_FOAM
  foam = waveFoamNear(vRelativeGridXZ);
#endif
  // The wake's foam (hull trail, bow wave) is the whitecaps' foam: the same material.
  foam = withWakeFoam(foam);
#ifdef OCEAN_IWAVE
  foam = max(foam, iwaveFoam(vIWaveSlope));
#endif
#ifdef OCEAN_COAST
  foam = max(foam, coastSurfFoam(vCoastLook, vCoastCarrier));
#endif
  if (foam > 0.0) {
#ifdef OCEAN_FOAM_TEXTURE
    color = foamOver(color, foam, n, v, vRelativeGridXZ);
#else
    float foamLight = 0.35 + 0.65 * clamp(uSunDirection.y * 2.0 + 0.3, 0.0, 1.0);
    color = mix(color, FOAM_COLOR * foamLight, foam);
#endif
  }

  color = mix(color, hazeColor(v), hazeWeight());
#ifdef OCEAN_OWN_ROLL_OFF
  color = rollOffHighlights(color);
#endif

#ifdef OCEAN_LOD_COLORS
  // The LOD debugger's band colours, near to far; the far rings and the skirt (bands past
  // the grid's) take the last one. The sea under them is clipped at white first, so that the
  // glint's light, many times white before the tone curve, does not wash them out.
  const vec3 bandColors[LOD_BAND_COUNT] = LOD_BAND_COLORS;
  color = mix(min(color, 1.0), bandColors[min(int(vBand + 0.5), LOD_BAND_COUNT - 1)], 0.7);
#endif

  gl_FragColor = vec4(color, uMarkSides ? 0.0 : 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
#endif
}
