// God rays: sunlight scattered towards the eye out of the shafts under the waves, marched
// along each line of sight through the bake of the shaft light (shaders/shaftLight.frag). Drawn
// at half the water pass's resolution (UnderwaterPost, the 'rays' pass: a quarter of the canvas's
// with the blur on), since the shafts are soft at that scale and the march is the underwater
// frame's dearest part, and read back by the water pass with one filtered fetch
// (shaders/underwater.frag; docs/shader-notes.md). Written with the scene
// target's encoding (src/render/underwater/sceneEncoding.ts): RGBA8, square roots up to 1, a shoulder above.

#include <packing>
#include <oceano_constants>
#include <oceano_tiled_heightmap>
#include <oceano_water_volume>
#include <oceano_line_of_sight>

uniform sampler2D tDepth;
// shaders/shaftLight.frag's bake of the shaft light, linearly filtered: one period of the
// lens, repeating, or with SHAFT_LIGHT_WINDOW (a wave model whose lens does not repeat on a
// small tile) a window around what the god rays read, its corner at uShaftOrigin.
uniform sampler2D tShaftLight;
uniform vec2 uShaftOrigin;
uniform float uShaftExtent;
uniform vec3 uRefractedSun;
uniform vec3 uSunColor;
uniform float uGodRays;

varying vec2 vUv;

// Each step is one filtered fetch of the bake. With a quarter of the water pass's pixels, 40
// steps read half the texels 20 at full resolution would, and keep the march's jitter grain,
// which the upsample spreads over 4 × 4 canvas pixels, fine (docs/shader-notes.md).
const int GOD_RAY_STEPS = 40;
// Shafts are followed GOD_RAY_RANGE metres along the line of sight (<oceano_constants>,
// from src/render/underwater/shaftLightTile.ts, which sizes the bake's window by it); fog hides what is beyond.
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
  vec4 nearView = nearViewPoint(vUv * 2.0 - 1.0);
  vec3 direction = normalize(nearWorldPoint(nearView) - uEye);
  float distance = sightDistance(nearView, texture2D(tDepth, vUv).x);
  gl_FragColor = vec4(godRays(uEye, direction, distance), 1.0);
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
}
