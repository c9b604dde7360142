// One radix-2 Stockham stage of an inverse FFT along x or z, for four complex signals at
// once (two RGBA float textures, two complex values each). Output texel o along the axis:
//   k = o mod Ns, j = ⌊o/2Ns⌋·Ns + k, r = ⌊o/Ns⌋ mod 2,
//   out[o] = in[j] + (−1)^r · e^{+iπk/Ns} · in[j + n/2]
// (Govindaraju et al. 2008; the same indexing, tested against fft.js, is in
// src/sim/stockhamFft.ts). The twiddles come from a table computed in float64 on the CPU.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uInput0;
uniform sampler2D uInput1;
uniform sampler2D uTwiddle;   // n/2 × 1: (cos, sin) of 2π m/n
uniform int uN;
uniform int uHalfSize;        // Ns = 2^stage
uniform bool uVertical;       // false: along x (texel column), true: along z (texel row)

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

vec2 mul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int o = uVertical ? texel.y : texel.x;
  int k = o % uHalfSize;
  int j = (o / (2 * uHalfSize)) * uHalfSize + k;
  float sign = ((o / uHalfSize) % 2 == 0) ? 1.0 : -1.0;
  vec2 w = sign * texelFetch(uTwiddle, ivec2(k * uN / (2 * uHalfSize), 0), 0).xy;
  ivec2 ia = uVertical ? ivec2(texel.x, j) : ivec2(j, texel.y);
  ivec2 ib = uVertical ? ivec2(texel.x, j + uN / 2) : ivec2(j + uN / 2, texel.y);
  vec4 a0 = texelFetch(uInput0, ia, 0);
  vec4 b0 = texelFetch(uInput0, ib, 0);
  vec4 a1 = texelFetch(uInput1, ia, 0);
  vec4 b1 = texelFetch(uInput1, ib, 0);
  out0 = vec4(a0.xy + mul(w, b0.xy), a0.zw + mul(w, b0.zw));
  out1 = vec4(a1.xy + mul(w, b1.xy), a1.zw + mul(w, b1.zw));
}
