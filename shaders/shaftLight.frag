// The light let through the surface, relative to a flat sea, baked once per frame for the
// god rays to read with one filtered fetch per step instead of four lens heights. It depends
// on the surface position only. Where the wave model's lens height repeats on a small tile
// (the seed's ripples: 96 m) one period is baked and read repeating; otherwise a window
// around everything the god rays read this frame (src/render/underwater/shaftLightTile.ts). Either way the
// texel (i, j) holds s = uShaftOrigin + (i + 1/2, j + 1/2) · uShaftExtent / size.

#include <oceano_waves>

uniform vec2 uShaftOrigin;
uniform float uShaftExtent;

varying vec2 vUv;

// Distance to the neighbours a crest is compared with, metres, and the contrast per metre
// of height difference.
const float SHAFT_REACH = 1.5;
const float SHAFT_CONTRAST = 6.0;

// A crest of the lens height (waveLensHeight, the model's short waves) higher than its
// surroundings is a converging lens: the band-passed height (centre minus the mean of three
// neighbours at 120°) gives the shafts, and they drift with the waves.
float shaftLight(vec2 s) {
  float centre = waveLensHeight(s);
  float around = waveLensHeight(s + SHAFT_REACH * vec2(1.0, 0.0))
               + waveLensHeight(s + SHAFT_REACH * vec2(-0.5, 0.866))
               + waveLensHeight(s + SHAFT_REACH * vec2(-0.5, -0.866));
  float lens = clamp(0.5 + SHAFT_CONTRAST * (centre - around / 3.0), 0.0, 1.0);
  return lens * lens * lens;
}

void main() {
  // vUv is the texel's centre.
  gl_FragColor = vec4(shaftLight(uShaftOrigin + vUv * uShaftExtent), 0.0, 0.0, 1.0);
}
