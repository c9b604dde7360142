// The last underwater pass at full resolution, with the blur on: the blurred water from
// half resolution where the pixel's line of sight starts in the water, the scene, sharp,
// where it starts in the air, then tone mapping and the output colour space (what
// OutputPass would do in a pass of its own), which the blur has already done for the water.

#include <packing>
#include <oceano_waves>
#include <oceano_water_volume>
#include <oceano_waterline>
#include <oceano_scene_decode>
#include <oceano_line_of_sight>

uniform sampler2D tDiffuse;
uniform sampler2D tDepth;
// Premultiplied: rgb is the blurred water colour as the canvas holds it (sRGB) times the share
// of water under the kernel, in a (shaders/gaussianBlur.frag, ENCODE_OUTPUT).
uniform sampler2D tBlurred;

varying vec2 vUv;

// Below this share of water the blurred colour is mostly rounding (half floats keep 11
// bits): a water pixel at the waterline with no water pixel within the kernel's reach at
// half resolution, which the fog alone then colours.
const float MIN_WATER_SHARE = 1.0 / 512.0;

// A linear colour as the canvas holds it: what three's tonemapping_fragment and
// colorspace_fragment do at the end of a shader, for the branches below that need it.
vec3 toCanvas(vec3 linear) {
#ifdef TONE_MAPPING
  linear = toneMapping(linear);
#endif
  return linearToOutputTexel(vec4(linear, 1.0)).rgb;
}

// Without PER_PIXEL_WATERLINE (the near plane is wholly under the water) every pixel is
// water and has water all around it: the blurred colour alone, which the blur already wrote
// as the canvas holds it (sRGB, shaders/gaussianBlur.frag, ENCODE_OUTPUT). perf: the cases
// are compiled apart rather than branched on a uniform: each program smaller on a GPU, and no
// untaken side on a software rasterizer, which runs both (docs/shader-notes.md).
void main() {
#ifdef PER_PIXEL_WATERLINE
  vec4 scene = texture2D(tDiffuse, vUv);
  vec4 nearView = nearViewPoint(vUv * 2.0 - 1.0);
  vec3 nearWorld = nearWorldPoint(nearView);
  float depthSample = texture2D(tDepth, vUv).x;
  vec4 blurred = texture2D(tBlurred, vUv);
  vec3 color;
  if (startsInAir(scene.a, depthSample, nearWorld)) {
    color = toCanvas(sceneColor(scene));
  } else if (blurred.a >= MIN_WATER_SHARE) {
    color = blurred.rgb / blurred.a;
  } else {
    // Fog alone, unblurred, for the few water pixels with no water beside them at half resolution.
    color = toCanvas(throughWater(sceneColor(scene), normalize(nearWorld - uEye), sightDistance(nearView, depthSample)));
  }
  gl_FragColor = vec4(color, 1.0);
#else
  vec4 blurred = texture2D(tBlurred, vUv);
  gl_FragColor = vec4(blurred.rgb / max(blurred.a, MIN_WATER_SHARE), 1.0);
#endif
}
