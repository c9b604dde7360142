// The sky as a sea of one roughness reflects it (skyCubeColorRough, shaders/skyCube.glsl),
// painted into a small cube of its own (src/render/sky/prefilteredSky.ts) whenever that
// roughness or the sky changes: the ocean's pixels then read it once, where they would read
// two levels of the sky and blend them. It holds the square root of the colour, as the sky's
// own cube does (shaders/skyCube.glsl says why).
#include <oceano_sky_cube>

uniform float uSlopeVariance;
varying vec3 vDirection;

void main() {
  gl_FragColor = vec4(sqrt(skyCubeColorRough(normalize(vDirection), uSlopeVariance)), 1.0);
}
