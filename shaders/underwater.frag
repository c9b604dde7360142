// The water between the eye and whatever the scene pass drew: fog and absorption by
// distance (from the depth buffer) and sunlight scattered out of the shafts under the
// waves (god rays, marched at half this pass's resolution by shaders/godRays.frag). With
// the blur on (uWriteMask) it runs at half resolution, since the blur softens it anyway, and writes premultiplied colour for the blur: (colour, 1) where
// the pixel's line of sight starts in the water, (0, 0, 0, 0) where it starts in the air;
// the full-resolution composite puts the sharp air side back. With the blur off it runs at
// full resolution and writes the final colour onto the canvas.

#include <packing>
#include <oceano_constants>
#include <oceano_waves>
#include <oceano_water_volume>
#include <oceano_waterline>
#include <oceano_scene_decode>
#include <oceano_line_of_sight>

uniform sampler2D tDiffuse;
uniform sampler2D tDepth;
// The god rays (shaders/godRays.frag), in the scene target's encoding, filtered up.
uniform sampler2D tGodRays;
// Whether the blur passes follow and need premultiplied colour with the water mask in alpha.
uniform bool uWriteMask;

varying vec2 vUv;

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
  vec4 nearView = nearViewPoint(ndc);
  vec3 nearWorld = nearWorldPoint(nearView);
  vec3 direction = normalize(nearWorld - uEye);

  // perf: PER_PIXEL_WATERLINE and GOD_RAYS are defines, not uniforms, so what a frame does
  // not need is compiled out: a smaller program on a GPU, and on a software rasterizer, which
  // runs both sides of a branch, no untaken side (docs/shader-notes.md).
#ifdef PER_PIXEL_WATERLINE
  if (startsInAir(scene.a, depthSample, nearWorld)) {
    gl_FragColor = uWriteMask ? vec4(0.0) : vec4(sceneColor(scene), 1.0);
  } else {
#endif
  vec3 color = throughWater(sceneColor(scene), direction, sightDistance(nearView, depthSample));
#ifdef GOD_RAYS
  color += sceneColor(texture2D(tGodRays, vUv));
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
