// The teaching views' greyscale pictures (src/render/teaching/panelFigure.ts): up to three
// squares, each a height field's values as grey (−range black, 0 mid-grey, +range white),
// read texel for texel (nearest). A square may mix two fields, as the sea mixes its two
// heightmaps: (1 − w)·first + w·second.
uniform sampler2D uFirst0;
uniform sampler2D uSecond0;
uniform sampler2D uFirst1;
uniform sampler2D uSecond1;
uniform sampler2D uFirst2;
uniform sampler2D uSecond2;
uniform int uCount;
// Each square's corners as fractions of the canvas, (left, bottom, right, top): the layout is
// computed once in TypeScript (src/sim/teaching/teachingFigures.ts), where the captions use it too.
uniform vec4 uRect[3];
uniform float uWeight[3];
uniform float uRange[3];
uniform int uChannel;   // 0: the value in r, 1: in g (the FFT cascades' height)

varying vec2 vUv;

float field(sampler2D map, vec2 uv) {
  vec4 texel = texture(map, uv);
  return uChannel == 1 ? texel.g : texel.r;
}

float mixed(sampler2D first, sampler2D second, float weight, vec2 uv) {
  return mix(field(first, uv), field(second, uv), weight);
}

void main() {
  vec3 color = vec3(0.12, 0.14, 0.16);
  for (int i = 0; i < 3; i++) {
    vec4 r = uRect[i];
    if (i >= uCount || vUv.x < r.x || vUv.x >= r.z || vUv.y < r.y || vUv.y >= r.w) continue;
    // Texture v runs up the square, as the fields' rows run along z.
    vec2 uv = (vUv - r.xy) / (r.zw - r.xy);
    float h = i == 0 ? mixed(uFirst0, uSecond0, uWeight[0], uv) : i == 1 ? mixed(uFirst1, uSecond1, uWeight[1], uv) : mixed(uFirst2, uSecond2, uWeight[2], uv);
    color = vec3(h / uRange[i] * 0.5 + 0.5);
  }
  gl_FragColor = vec4(color, 1.0);
}
