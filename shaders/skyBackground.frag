// The cube map along each pixel's view ray, as three.js's background draws it: the same
// mirror for image cube maps, then the renderer's tone mapping and output colour space.

#include <oceano_sky_cube>
varying vec3 vRay;

void main() {
  vec3 direction = normalize(vRay);
  gl_FragColor = vec4(skyCubeColor(direction), 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
}
