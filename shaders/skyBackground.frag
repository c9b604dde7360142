// The cube map along each pixel's view ray, as three.js's background draws it: the same
// mirror for image cube maps, then the sun's disc in its full brightness, then the renderer's
// tone mapping and output colour space.

#include <oceano_sky_cube>
#include <oceano_sun_disc>

uniform vec3 uSunDirection;
// The disc's radiance over the cube's white (src/sim/optics/sunDisc.ts): the sky painted from
// the sun holds its disc only as white, 1, which an 8-bit cube cannot exceed. Zero for a cube
// map of the user's, whose sun lies in its own pixels.
uniform vec3 uSunRadiance;
varying vec3 vRay;

void main() {
  vec3 direction = normalize(vRay);
  vec3 sky = skyCubeColor(direction) + uSunRadiance * insideSunDisc(direction, uSunDirection);
  gl_FragColor = vec4(sky, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
}
