// Water shading. From above: Fresnel-weighted mix of the reflected sky cube and the
// water's own colour, a sun highlight, and haze towards the horizon. From below: the sky
// refracted through Snell's window, total internal reflection of the water outside it.

// Tells a wave-model chunk it is compiled for the ocean's pixels (normals and foam only), where
// it may read its fields more cheaply than the vertex stage (shaders/waves/fft.glsl).
#define WAVE_FRAGMENT_STAGE
#include <oceano_water_volume>
#include <oceano_constants>
#include <oceano_waves>

#include <oceano_sky_cube>
uniform sampler2D uFresnelTable;
uniform sampler2D uFresnelFromBelow;
uniform bool uFresnelEnabled;
// Set while the frame goes through the underwater passes, which read the side from alpha.
uniform bool uMarkSides;
uniform vec3 uDeepColor;
uniform vec3 uFacingTint;
uniform vec3 uSunDirection;
uniform vec3 uSunColor;
uniform float uHazeDensity;
// The teaching view of the normal itself as a colour (OCEAN_SHOW_NORMALS) and the LOD
// debugger's band tint (OCEAN_LOD_COLORS) are compiled in only while shown: SwiftShader runs
// a branch's body for every pixel even when a uniform says no, and the tint's indexed
// constant array alone was about 10 of the default view's 218 ms (scripts/shaderVariantProbe.ts).

// The pixel's position and the eye's relative to the render origin (see ocean.vert).
varying vec3 vRelativePosition;
uniform vec3 uEyeRelative;
uniform mat4 uViewRelative;
varying vec3 vNormal;
#ifdef OCEAN_NEAR_BANDS
varying vec3 vHorizon;
varying float vHaze;
#endif
varying float vBand;
varying vec2 vGridXZ;
varying vec2 vRelativeGridXZ;
varying vec2 vWakeSlope;
flat varying float vVertexSpacing;
varying float vWaveFade;
varying float vWakeFoam;
// The boat's wake is on (its uniforms live in the vertex shader's oceano_wake chunk). Its
// code is compiled in only with OCEAN_WAKE (OceanMaterial.setWakeOn).
uniform bool uWakeOn;
uniform bool uFlatNormals;
// waves=fft teaching view (OCEAN_NORMALS_COMPARE, compiled in only while shown): slope normals
// per pixel on the left half of the screen, the fabricated normals per vertex (interpolated,
// from ocean.vert) on the right.

// A spectral sea's foam is sea water whipped with air: white, lit by sun and sky.
const vec3 FOAM_COLOR = vec3(0.82, 0.86, 0.88);

#ifdef OCEAN_LOD_COLORS
// The LOD debugger's band colours, near to far; the far rings and the skirt (bands past
// the grid's) take the last one.
const vec3 BAND_COLORS[LOD_BAND_COUNT] = LOD_BAND_COLORS;
#endif

// x⁹⁰⁰, the sun's highlight, by squaring (900 = 512 + 256 + 128 + 4): eleven products cost
// SwiftShader less than pow's log and exp (the default view about 3 % less,
// scripts/shaderVariantProbe.ts), and agree with pow to float32 rounding.
float power900(float x) {
  float x4 = x * x;
  x4 *= x4;
  float x128 = x4 * x4;
  x128 *= x128;
  x128 *= x128;
  x128 *= x128;
  x128 *= x128;
  float x256 = x128 * x128;
  return x256 * x256 * x256 * x128 * x4;
}

// Linear interpolation between table entries done by hand: float textures are not
// filterable everywhere in WebGL2.
float fresnelLookup(sampler2D table, float cosIncidence) {
  int size = textureSize(table, 0).x;
  float x = clamp(cosIncidence, 0.0, 1.0) * float(size - 1);
  int i = int(floor(x));
  int j = min(i + 1, size - 1);
  float a = texelFetch(table, ivec2(i, 0), 0).r;
  float b = texelFetch(table, ivec2(j, 0), 0).r;
  return mix(a, b, x - float(i));
}

// The underside's shading is compiled in only while the view may be under the water
// (OceanMaterial.setSeenFromBelow; otherwise only front faces are drawn): SwiftShader runs
// both sides of a branch, so an untaken gl_FrontFacing branch would still cost every pixel.
#ifdef OCEAN_SEEN_FROM_BELOW
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
    through = skyCubeColor(t);
    float sunVisible = step(0.0, uSunDirection.y);
    through += uSunColor * pow(max(dot(t, uSunDirection), 0.0), 700.0) * 30.0 * sunVisible;
  }
  vec3 mirrored = waterVolumeColor(reflect(-v, towardsWater));
  return mix(through, mirrored, reflectance);
}
#endif

void main() {
  vec3 toEye = uEyeRelative - vRelativePosition;
  float distance = length(toEye);
  vec3 v = toEye / distance;
  vec3 n = normalize(vNormal);
#ifdef WAVE_PIXEL_FIELDS
  // The model's per-pixel fields, read once here, outside every branch (shaders/waves/fft.glsl).
  wavePixelFields(vRelativeGridXZ, true);
#endif
#ifdef WAVE_PIXEL_NORMALS
  // Exact normals (spectral slopes, or the Gerstner sum's closed form) at this pixel's own
  // grid point, not interpolated between vertices: the mapping from grid to displaced
  // surface is smooth, so interpolating the grid point is exact to first order.
#ifdef OCEAN_NORMALS_COMPARE
  bool fabricatedHalf = (uViewRelative * vec4(vRelativePosition, 1.0)).x > 0.0;
#else
  const bool fabricatedHalf = false;
#endif
  if (!uFlatNormals && !fabricatedHalf) {
    // At the grid point relative to the render origin: exact 10⁶ m out, where vGridXZ moves in 6 cm steps.
    n = waveNormalNear(vRelativeGridXZ);
    // The wake's slope is interpolated from the vertices (its waves are 8 m and longer).
#ifdef OCEAN_WAKE
    if (uWakeOn) n = normalize(vec3(n.x - vWakeSlope.x * n.y, n.y, n.z - vWakeSlope.y * n.y));
#endif
  }
#endif
// OCEAN_NEAR_BANDS: the material of the bands whose vertices lie at most DETAIL_FROM apart,
// where the weight below is exactly 0 (OceanMaterial.near): SwiftShader would run the block
// for every pixel even where `weight > 0.0` is false, so it is left out there.
// OCEAN_ONLY_FROM_BELOW: seen from under the water the far bands lie at grazing angles behind
// the fog, outside Snell's window, where the mirrored water colour hardly depends on the normal:
// the block is left out there too (its effect on the underwater references is measured in
// tests/browser/underwater.test.ts).
#if defined(WAVE_DETAIL_NORMALS) && !defined(OCEAN_NEAR_BANDS) && !defined(OCEAN_ONLY_FROM_BELOW)
  // A model whose normals are per vertex loses its short waves where the band's vertices
  // are farther apart than they are long (48 m in band 5, the ripples are a few metres):
  // the far sea goes flat. There the normal is evaluated per pixel instead, faded in as
  // the vertex spacing grows past DETAIL_FROM (flat per chunk, so exactly 0 below it) and out again as the pixel's footprint on
  // the sea grows past the ripples' length, where the detail could only alias (a normal
  // map would need mipmapped slopes there). Near the camera, and in the default view
  // (whose far bands are seen at grazing angles, footprints of tens of metres), the
  // weight is 0 and the picture is unchanged.
  // Band 2 (6 m) keeps its vertex normals, band 3 (12 m) and coarser get the full detail.
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
      n = normalize(mix(n, detail, weight));
    }
  }
#endif
#ifdef OCEAN_SHOW_NORMALS
  // (n + 1) / 2, written without tone mapping.
  gl_FragColor = vec4(n * 0.5 + 0.5, 1.0);
  return;
#endif
  // With uMarkSides, alpha tells the underwater pass which side of this very mesh the line
  // of sight came from: 0.5 from below, 0 from above. Drawn straight to the canvas it is 1.
#if defined(OCEAN_ONLY_FROM_BELOW)
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
  float cosIncidence = max(dot(n, v), 0.0);

  float reflectance = uFresnelEnabled ? fresnelLookup(uFresnelTable, cosIncidence) : 0.5;

  vec3 r = reflect(-v, n);
  // A reflected ray that points below the horizon would see the sea, not the sky.
  r.y = max(r.y, 0.0);
  vec3 sky = skyCubeColor(normalize(r));

  vec3 water = mix(uDeepColor, uFacingTint, cosIncidence * cosIncidence);
  vec3 color = mix(water, sky, reflectance);

  vec3 halfway = normalize(uSunDirection + v);
  float sunVisible = step(0.0, uSunDirection.y);
  float specular = power900(max(dot(n, halfway), 0.0)) * 40.0;
  color += uSunColor * specular * reflectance * sunVisible;

  float foam = 0.0;
#ifdef WAVE_FOAM
  foam = waveFoamNear(vRelativeGridXZ);
#endif
  // The wake's foam (hull trail, bow wave) looks like the whitecaps: the same white, lit alike.
#ifdef OCEAN_WAKE
  if (uWakeOn) foam = max(foam, vWakeFoam);
#endif
  if (foam > 0.0) {
    float foamLight = 0.35 + 0.65 * clamp(uSunDirection.y * 2.0 + 0.3, 0.0, 1.0);
    color = mix(color, FOAM_COLOR * foamLight, foam);
  }

  // The haze's colour is the sky at the horizon beyond the pixel. In the near bands (vertices
  // 2-6 m apart, OCEAN_NEAR_BANDS) it is looked up per vertex and interpolated: where the haze
  // weighs anything (300 m and more: 1 - exp(-0.36) = 0.3) a triangle spans about a degree of
  // azimuth, too little for the sky's colour to bend; every reference view moved by at most
  // 0.042 levels on average. The cube lookup per pixel was about 16 of the default view's
  // 218 ms (scripts/shaderVariantProbe.ts). The far bands, rings and skirt, whose cells span
  // kilometres where the haze is near 1, keep the exact lookup per pixel.
  // Its weight, 1 - exp(-distance · density), is interpolated from the vertices there too: across
  // a triangle of side h at distance d the distance is linear but for about h² / 8d (a millimetre
  // at most, where h is a few metres and d at least the eye's height), so the weight moves by
  // under 1e-5; the exponential per pixel was about 16 of the default view's 123 ms.
#ifdef OCEAN_NEAR_BANDS
  vec3 horizon = vHorizon;
  float haze = vHaze;
#else
  vec3 horizon = skyCubeColor(normalize(vec3(-v.x, 0.0, -v.z)));
  float haze = 1.0 - exp(-distance * uHazeDensity);
#endif
  color = mix(color, horizon, haze);

#ifdef OCEAN_LOD_COLORS
  color = mix(color, BAND_COLORS[min(int(vBand + 0.5), LOD_BAND_COUNT - 1)], 0.7);
#endif

  gl_FragColor = vec4(color, uMarkSides ? 0.0 : 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
#endif
}
