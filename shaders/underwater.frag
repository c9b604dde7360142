// The water between the eye and whatever the scene pass drew: fog and absorption by
// distance (from the depth buffer) and sunlight scattered out of the shafts under the
// waves (god rays). Writes alpha = 1 where the pixel's line of sight starts in the water
// and 0 where it starts in the air, for the blur passes.

#include <packing>
#include <oceano_waves>
#include <oceano_water_volume>

uniform sampler2D tDiffuse;
uniform sampler2D tDepth;
uniform mat4 uProjectionInverse;
uniform mat4 uCameraWorld;
uniform vec3 uEye;
uniform float uNear;
uniform float uFar;
uniform bool uPerPixelWaterline;
uniform vec3 uRefractedSun;
uniform vec3 uSunColor;
uniform float uGodRays;
// Whether the blur passes follow and need the water mask in alpha; else alpha is 1 for the canvas.
uniform bool uWriteMask;

varying vec2 vUv;

const int GOD_RAY_STEPS = 10;
// Shafts are followed this far along the line of sight, metres; fog hides what is beyond.
const float GOD_RAY_RANGE = 60.0;
// Depth over which the shafts' contrast fades as their focus blurs, metres.
const float SHAFT_FADE_DEPTH = 30.0;
// Distance to the neighbours a crest is compared with, metres, and the contrast per metre
// of height difference.
const float SHAFT_REACH = 1.5;
const float SHAFT_CONTRAST = 6.0;
// Brightness of the shafts at intensity 1: in-scattering made visible on an 8-bit screen.
const float GOD_RAY_GAIN = 1.5;

// Interleaved gradient noise: a fixed per-pixel offset of the march, so 10 steps read as
// smooth shafts after the blur instead of as bands. Deterministic, no seed involved.
float marchJitter(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// Light let through the surface at s, relative to a flat sea. A ripple crest higher than
// its surroundings is a converging lens: the band-passed ripple height (centre minus the
// mean of three neighbours at 120°) gives the shafts, and they drift with the ripples.
float shaftLight(vec2 s) {
  float centre = waveLensHeight(s);
  float around = waveLensHeight(s + SHAFT_REACH * vec2(1.0, 0.0))
               + waveLensHeight(s + SHAFT_REACH * vec2(-0.5, 0.866))
               + waveLensHeight(s + SHAFT_REACH * vec2(-0.5, -0.866));
  float lens = clamp(0.5 + SHAFT_CONTRAST * (centre - around / 3.0), 0.0, 1.0);
  return lens * lens * lens;
}

vec3 godRays(vec3 origin, vec3 direction, float distance) {
  if (uGodRays <= 0.0 || uRefractedSun.y >= 0.0) return vec3(0.0);
  float range = min(distance, GOD_RAY_RANGE);
  float stepLength = range / float(GOD_RAY_STEPS);
  float jitter = marchJitter(gl_FragCoord.xy);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < GOD_RAY_STEPS; i++) {
    vec3 p = origin + direction * ((float(i) + jitter) * stepLength);
    float depth = -p.y;
    if (depth <= 0.0) continue;
    // Where the sunlight reaching p crossed the surface.
    vec2 s = p.xz - uRefractedSun.xz * (p.y / uRefractedSun.y);
    float contrast = exp(-depth / SHAFT_FADE_DEPTH);
    float along = (float(i) + jitter) * stepLength;
    vec3 reach = waterTransmittance(along + depth / -uRefractedSun.y);
    sum += reach * shaftLight(s) * contrast;
  }
  // Forward scattering: the shafts glow most when looking towards the sun.
  float towardsSun = max(dot(direction, -uRefractedSun), 0.0);
  float phase = 0.3 + 3.0 * pow(towardsSun, 4.0);
  return uSunColor * sum * stepLength * uFogDensity * phase * GOD_RAY_GAIN * uGodRays;
}

// Where the line of sight hit the ocean mesh, the face it hit says which side it came
// from (the ocean writes alpha 0 on its top, 0.5 on its underside): that follows the drawn
// triangles exactly, so the waterline has no gap. Elsewhere (sky, sea bed, other meshes)
// the near-plane point is compared with the surface height above it.
bool startsInAir(float alpha, float depthSample, vec3 nearWorld) {
  if (depthSample < 1.0 && alpha < 0.25) return true;
  if (depthSample < 1.0 && alpha < 0.75) return false;
  return nearWorld.y >= waveDisplacement(nearWorld.xz).y;
}

void main() {
  vec4 scene = texture2D(tDiffuse, vUv);
  vec4 nearView = uProjectionInverse * vec4(vUv * 2.0 - 1.0, -1.0, 1.0);
  nearView /= nearView.w;
  vec3 nearWorld = (uCameraWorld * nearView).xyz;
  vec3 direction = normalize(nearWorld - uEye);

  float depthSample = texture2D(tDepth, vUv).x;
  if (uPerPixelWaterline && startsInAir(scene.a, depthSample, nearWorld)) {
    gl_FragColor = vec4(scene.rgb, uWriteMask ? 0.0 : 1.0);
    return;
  }

  float distance = 1e6;
  if (depthSample < 1.0) {
    float viewZ = perspectiveDepthToViewZ(depthSample, uNear, uFar);
    distance = length(nearView.xyz * (viewZ / nearView.z));
  }
  vec3 color = throughWater(scene.rgb, direction, distance);
  color += godRays(uEye, direction, distance);
  gl_FragColor = vec4(color, 1.0);
}
