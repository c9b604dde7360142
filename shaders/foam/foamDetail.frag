// The foam's detail texture, drawn once (src/render/foam/foamDetail.ts): one tile of sea foam,
// repeating, that the ocean's pixels sample to turn "how much foam" into what foam looks like
// (shaders/foam/foamMaterial.glsl). Everything here repeats with the tile, so the texture wraps.
//   r: density in [0, 1]. Foam of thickness f shows where the density is above 1 − f, so thin
//      foam is the densest lace only and thick foam is solid: the edges feather as foam thins.
//   g, b: the density's slope along u and v (0.5 = flat), for the foam's own bumpy normal.
// The density is the lace of bubbles (Voronoi cells: bubbles are the cells, foam the walls
// between them; Worley 1996, "A cellular texture basis function"), at two sizes, over a
// fractal of value noise that makes the patches thick in places and thin in others.
precision highp float;

varying vec2 vUv;

// Cells per tile of the two bubble sizes and the fractal's first octave.
const float BIG_BUBBLES = 9.0;
const float SMALL_BUBBLES = 29.0;
const float PATCHES = 8.0;

float hash(vec2 cell, float salt) {
  return fract(sin(dot(cell, vec2(127.1, 311.7)) + salt * 74.7) * 43758.5453);
}

// Distances to the nearest and second nearest cell centre, on a lattice of `cells` per tile that wraps.
vec2 worley(vec2 uv, float cells, float salt) {
  vec2 p = uv * cells;
  vec2 base = floor(p);
  float first = 9.0;
  float second = 9.0;
  for (int j = -1; j <= 1; j++) {
    for (int i = -1; i <= 1; i++) {
      vec2 cell = base + vec2(float(i), float(j));
      vec2 wrapped = mod(cell, cells);
      vec2 centre = cell + vec2(hash(wrapped, salt), hash(wrapped, salt + 1.0));
      float d = length(p - centre);
      if (d < first) {
        second = first;
        first = d;
      } else if (d < second) {
        second = d;
      }
    }
  }
  return vec2(first, second);
}

// Smooth value noise on a wrapping lattice of `cells` per tile, in [0, 1].
float valueNoise(vec2 uv, float cells, float salt) {
  vec2 p = uv * cells;
  vec2 base = floor(p);
  vec2 w = p - base;
  w = w * w * (3.0 - 2.0 * w);
  float a = hash(mod(base, cells), salt);
  float b = hash(mod(base + vec2(1.0, 0.0), cells), salt);
  float c = hash(mod(base + vec2(0.0, 1.0), cells), salt);
  float d = hash(mod(base + vec2(1.0, 1.0), cells), salt);
  return mix(mix(a, b, w.x), mix(c, d, w.x), w.y);
}

float density(vec2 uv) {
  float patches = 0.0;
  float amplitude = 0.5;
  float cells = PATCHES;
  for (int octave = 0; octave < 4; octave++) {
    patches += amplitude * valueNoise(uv, cells, float(octave));
    amplitude *= 0.5;
    cells *= 2.0;
  }
  patches /= 0.9375;
  // Walls between big bubbles, thinning towards their middles; small bubbles punched through.
  vec2 big = worley(uv, BIG_BUBBLES, 11.0);
  float walls = 1.0 - smoothstep(0.0, 0.45, big.y - big.x);
  vec2 small = worley(uv, SMALL_BUBBLES, 23.0);
  float holes = smoothstep(0.45, 0.2, small.x);
  float lace = walls * (1.0 - 0.6 * holes);
  return clamp(0.62 * patches + 0.5 * lace - 0.08, 0.0, 1.0);
}

void main() {
  float texel = 1.0 / 512.0;
  float d = density(vUv);
  float du = density(vUv + vec2(texel, 0.0)) - density(vUv - vec2(texel, 0.0));
  float dv = density(vUv + vec2(0.0, texel)) - density(vUv - vec2(0.0, texel));
  gl_FragColor = vec4(d, 0.5 + 4.0 * du, 0.5 + 4.0 * dv, 1.0);
}
