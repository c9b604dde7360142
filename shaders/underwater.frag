// The water between the eye and whatever the scene pass drew: fog and absorption by
// distance (from the depth buffer) and sunlight scattered out of the shafts under the
// waves (god rays). With the blur on (uWriteMask) it runs at half resolution, since the
// blur softens it anyway, and writes premultiplied colour for the blur: (colour, 1) where
// the pixel's line of sight starts in the water, (0, 0, 0, 0) where it starts in the air;
// the full-resolution composite puts the sharp air side back. With the blur off it runs at
// full resolution and writes the final colour onto the canvas.

#include <packing>
#include <oceano_constants>
#include <oceano_waves>
#include <oceano_tiled_heightmap>
#include <oceano_water_volume>
#include <oceano_waterline>
#include <oceano_scene_decode>

uniform sampler2D tDiffuse;
// shaders/shaftLight.frag's bake of the shaft light, linearly filtered: one period of the
// lens, repeating, or with SHAFT_LIGHT_WINDOW (a wave model whose lens does not repeat on a
// small tile) a window around what the god rays read, its corner at uShaftOrigin.
uniform sampler2D tShaftLight;
uniform vec2 uShaftOrigin;
uniform float uShaftExtent;
uniform sampler2D tDepth;
uniform mat4 uProjectionInverse;
uniform mat4 uCameraWorld;
uniform vec3 uEye;
uniform float uNear;
uniform float uFar;
uniform vec3 uRefractedSun;
uniform vec3 uSunColor;
uniform float uGodRays;
// Whether the blur passes follow and need premultiplied colour with the water mask in alpha.
uniform bool uWriteMask;

varying vec2 vUv;

// 20 steps: at half resolution the march's jitter grain is two pixels wide and the blur
// hides less of it than of 10 steps at full resolution; each step is one filtered fetch.
const int GOD_RAY_STEPS = 20;
// Shafts are followed GOD_RAY_RANGE metres along the line of sight (<oceano_constants>,
// from src/sim/shaftLightTile.ts, which sizes the bake's window by it); fog hides what is beyond.
// Depth over which the shafts' contrast fades as their focus blurs, metres.
const float SHAFT_FADE_DEPTH = 30.0;
// Brightness of the shafts at intensity 1: in-scattering made visible on an 8-bit screen.
const float GOD_RAY_GAIN = 1.5;

// Interleaved gradient noise: a fixed per-pixel offset of the march, so the steps read as
// smooth shafts after the blur instead of as bands. Deterministic, no seed involved.
float marchJitter(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// Where the march starts reading the bake, in units of its side: the surface point s relative
// to the window's corner, or within one period of the repeating lens. Only the start is reduced:
// the march then adds steps of at most GOD_RAY_RANGE in these units, and the texture unit
// wraps a repeating bake itself, so each step is one filtered fetch and no arithmetic.
vec2 shaftLightCoordinate(vec2 s) {
#ifdef SHAFT_LIGHT_WINDOW
  return (s - uShaftOrigin) / uShaftExtent;
#else
  return wrapToTile(s, uShaftExtent) / uShaftExtent;
#endif
}

// Along the line of sight p(t) = origin + t · direction, every factor of a step is an
// exponential of something linear in t (the depth, the path the light took, where it
// crossed the surface), so the march steps them by constant factors: one filtered fetch
// and a few multiplications per step, the exponentials computed once.
vec3 godRays(vec3 origin, vec3 direction, float distance) {
  if (uRefractedSun.y >= 0.0) return vec3(0.0);
  float range = min(distance, GOD_RAY_RANGE);
  float stepLength = range / float(GOD_RAY_STEPS);
  float t = marchJitter(gl_FragCoord.xy) * stepLength;
  // depth(t) = -p.y; the sunlight reaching p crossed the surface at s(t) and travelled
  // depth / -uRefractedSun.y in the water before turning along the line of sight.
  float depth = -(origin.y + direction.y * t);
  float depthStep = -direction.y * stepLength;
  vec2 s = origin.xz + direction.xz * t - uRefractedSun.xz * ((origin.y + direction.y * t) / uRefractedSun.y);
  vec2 sStep = (direction.xz - uRefractedSun.xz * (direction.y / uRefractedSun.y)) * (stepLength / uShaftExtent);
  vec2 shaft = shaftLightCoordinate(s);
  // contrast · reach = exp(-depth / SHAFT_FADE_DEPTH) · waterTransmittance(t + depth / -uRefractedSun.y)
  vec3 extinction = uFogDensity * WATER_EXTINCTION;
  vec3 weight = exp(-depth / SHAFT_FADE_DEPTH - extinction * (t - depth / uRefractedSun.y));
  vec3 weightStep = exp(-depthStep / SHAFT_FADE_DEPTH - extinction * (stepLength - depthStep / uRefractedSun.y));
  vec3 sum = vec3(0.0);
  for (int i = 0; i < GOD_RAY_STEPS; i++) {
    // Points above the surface (a line of sight leaving the water) add nothing; their
    // weight can be large (up to e^70 at the densest fog), so it is not multiplied by 0.
    if (depth > 0.0) sum += weight * texture2D(tShaftLight, shaft).r;
    depth += depthStep;
    shaft += sStep;
    weight *= weightStep;
  }
  // Forward scattering: the shafts glow most when looking towards the sun.
  float towardsSun = max(dot(direction, -uRefractedSun), 0.0);
  float phase = 0.3 + 3.0 * pow(towardsSun, 4.0);
  return uSunColor * sum * stepLength * uFogDensity * phase * GOD_RAY_GAIN * uGodRays;
}

void main() {
#ifdef PER_PIXEL_WATERLINE
  // Across the waterline, a filtered read would mix air pixels into water ones (a bright
  // rim on the water side): one pixel is read, and its own waterline test decides.
  ivec2 texel = ivec2(vUv * vec2(textureSize(tDiffuse, 0)));
  vec4 scene = texelFetch(tDiffuse, texel, 0);
  float depthSample = texelFetch(tDepth, texel, 0).x;
  vec2 ndc = (vec2(texel) + 0.5) / vec2(textureSize(tDiffuse, 0)) * 2.0 - 1.0;
#else
  vec4 scene = texture2D(tDiffuse, vUv);
  float depthSample = texture2D(tDepth, vUv).x;
  vec2 ndc = vUv * 2.0 - 1.0;
#endif
  vec4 nearView = uProjectionInverse * vec4(ndc, -1.0, 1.0);
  nearView /= nearView.w;
  vec3 nearWorld = (uCameraWorld * nearView).xyz;
  vec3 direction = normalize(nearWorld - uEye);

  // PER_PIXEL_WATERLINE and GOD_RAYS are defines, not uniforms: SwiftShader runs both
  // sides of a branch, so what a frame does not need is compiled out.
#ifdef PER_PIXEL_WATERLINE
  if (startsInAir(scene.a, depthSample, nearWorld)) {
    gl_FragColor = uWriteMask ? vec4(0.0) : vec4(sceneColor(scene), 1.0);
  } else {
#endif
  float distance = 1e6;
  if (depthSample < 1.0) {
    float viewZ = perspectiveDepthToViewZ(depthSample, uNear, uFar);
    distance = length(nearView.xyz * (viewZ / nearView.z));
  }
  vec3 color = throughWater(sceneColor(scene), direction, distance);
#ifdef GOD_RAYS
  color += godRays(uEye, direction, distance);
#endif
  gl_FragColor = vec4(color, 1.0);
#ifdef PER_PIXEL_WATERLINE
  }
#endif
  // Into the half-resolution target (blur on) three.js makes these nothing; onto the canvas
  // (blur off, the last pass) they are the output's tone mapping and colour space.
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}
