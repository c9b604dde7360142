// The cube map along each pixel's view ray, as three.js's background draws it: the same
// mirror for image cube maps, then the sun's disc in its full brightness, then the renderer's
// tone mapping and output colour space. The square round the disc (sunDiscSprite.vert) draws
// with it too, giving the disc's edge its share of each pixel.

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
  vec3 sky = skyCubeColor(direction);
#if defined(OCEANO_DISC_THROUGH_ROLL_OFF) && defined(TONE_MAPPING)
  // Only the square round the disc (src/render/sky/sunDiscSprite.ts), under our curve. What a
  // pixel's many samples would show after the curve is the disc's share of the disc's white and
  // the rest of the sky as the curve shows it; the light drawn is the one the curve
  // (shaders/highlightRollOff.glsl) shows as that: its inverse.
  float share = sunDiscPixelShare(direction, uSunDirection);
  vec3 shown = mix(rollOffHighlights(toneMappingExposure * sky), rollOffHighlights(toneMappingExposure * (sky + uSunRadiance)), share);
  sky = unrollHighlights(shown) / toneMappingExposure;
#else
  sky += uSunRadiance * insideSunDisc(direction, uSunDirection);
#endif
  gl_FragColor = vec4(sky, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
}
