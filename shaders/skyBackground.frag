// The cube map along each pixel's view ray, as three.js's background draws it: the same
// mirror for image cube maps, then the renderer's tone mapping and output colour space.

uniform samplerCube uSky;
// -1 for a cube map made from images (three mirrors those in x), +1 for a cube render target.
uniform float uSkyFlip;
varying vec3 vRay;

void main() {
  vec3 direction = normalize(vRay);
  gl_FragColor = textureCube(uSky, vec3(uSkyFlip * direction.x, direction.y, direction.z));
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}
