// The seed's "Texturas y Heightmaps" figure: the two Perlin heightmaps as greyscale
// images, side by side, exactly as uploaded (the first channel of each gathered texel).
// Under waves=fft the same figure for the spectral sea: the largest and the smallest
// cascade's height (channel g of their displacement textures), each scaled by its range.
uniform sampler2D uHeightmap0;
uniform sampler2D uHeightmap1;
uniform float uAspect;
uniform int uChannel;   // 0: height in r, 1: in g
uniform vec2 uRange;    // height drawn white, per map

varying vec2 vUv;

void main() {
  // Two squares centred on the screen, whatever its aspect ratio.
  vec2 p = vec2((vUv.x - 0.5) * uAspect, vUv.y - 0.5) / 0.9;
  vec2 uv = vec2(p.x + 1.0, p.y + 0.5);
  vec3 color = vec3(0.12, 0.14, 0.16);
  if (uv.y >= 0.0 && uv.y < 1.0 && uv.x >= 0.0 && uv.x < 2.0) {
    bool second = uv.x >= 1.0;
    float gap = 0.02;
    vec2 local = vec2(fract(uv.x), uv.y);
    if ((second && local.x > gap) || (!second && local.x < 1.0 - gap)) {
      vec2 squeezed = second ? vec2((local.x - gap) / (1.0 - gap), local.y) : vec2(local.x / (1.0 - gap), local.y);
      vec4 texel = second ? texture(uHeightmap1, squeezed) : texture(uHeightmap0, squeezed);
      float h = (uChannel == 1 ? texel.g : texel.r) / (second ? uRange.y : uRange.x);
      color = vec3(h * 0.5 + 0.5);
    }
  }
  gl_FragColor = vec4(color, 1.0);
}
