// Moves the iWave grid by whole texels as its centre follows the camera's focus, the twin of
// IWaveGrid.scroll in src/sim/iwave/iwaveGrid.ts: texel p takes what stood at p + shift, and
// what scrolls in from past the edge starts calm.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uHeights;
uniform int uN;
uniform ivec2 uShift;

out vec4 outHeights;

void main() {
  ivec2 source = ivec2(gl_FragCoord.xy) + uShift;
  bool inside = source.x >= 0 && source.y >= 0 && source.x < uN && source.y < uN;
  outHeights = inside ? texelFetch(uHeights, source, 0) : vec4(0.0);
}
