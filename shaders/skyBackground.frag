// The cube map along each pixel's view ray, as three.js's background draws it: the same
// mirror for image cube maps, then the sun's disc in its full brightness, then the renderer's
// tone mapping and output colour space. In a small square round the disc
// (src/render/sky/sunDiscSquare.ts) the disc's edge gets its share of each pixel.

#include <oceano_sky_cube>
#include <oceano_sun_disc>

uniform vec3 uSunDirection;
// The disc's radiance over the cube's white (src/sim/optics/sunDisc.ts): the sky painted from
// the sun holds its disc only as white, 1, which an 8-bit cube cannot exceed. Zero for a cube
// map of the user's, whose sun lies in its own pixels.
uniform vec3 uSunRadiance;
uniform vec2 uDiscCentre;   // the square's centre, in normalised device coordinates
uniform vec2 uDiscHalfSize; // its half size there; zero: no square
varying vec3 vRay;
varying vec2 vClip;

void main() {
  vec3 direction = normalize(vRay);
  vec3 sky = skyCubeColor(direction);
#if defined(OCEANO_DISC_THROUGH_ROLL_OFF) && defined(TONE_MAPPING)
  // The share's derivative is taken here, where every pixel of a 2 × 2 block runs it.
  float share = sunDiscPixelShare(direction, uSunDirection);
  if (all(lessThan(abs(vClip - uDiscCentre), uDiscHalfSize))) {
    // Only the square round the disc, under our curve. What a pixel's many samples would show
    // after the curve is the disc's share of the disc's white and the rest of the sky as the
    // curve shows it; the light drawn is the one the curve (shaders/highlightRollOff.glsl)
    // shows as that: its inverse.
    vec3 shown = mix(rollOffHighlights(toneMappingExposure * sky), rollOffHighlights(toneMappingExposure * (sky + uSunRadiance)), share);
    sky = unrollHighlights(shown) / toneMappingExposure;
  } else {
    sky += uSunRadiance * insideSunDisc(direction, uSunDirection);
  }
#else
  sky += uSunRadiance * insideSunDisc(direction, uSunDirection);
#endif
  gl_FragColor = vec4(sky, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
}
