// One Stockham stage of an inverse FFT along x or z, for four complex signals at once (two
// RGBA float textures, two complex values each): radix 2, or radix 4 where RADIX_4 is defined
// (one radix-4 stage does the work of two radix-2 stages in one pass: half the passes, half the
// render-target writes). With R the radix and Ns the product of the radices of the stages
// before, output texel o along the axis takes
//   k = o mod Ns, j = ⌊o/(R·Ns)⌋·Ns + k, r = ⌊o/Ns⌋ mod R, θ = 2πk/(R·Ns),
//   out[o] = Σ_{m<R} e^{2πi·m·r/R} · e^{i·m·θ} · in[j + m·n/R]
// (Govindaraju et al. 2008, "High performance discrete Fourier transforms on graphics
// processors", the mixed-radix Stockham formulation; with R = 2 it is the radix-2 indexing of
// src/sim/waves/fft/stockhamFft.ts, tested against fft.js). The twiddles e^{2πi·q/n} come from a table
// computed in float64 on the CPU (m·k·n/(R·Ns) < n).
// The input is an atlas: several n × n grids (tiles) side by side along x, one per cascade, so
// one pass transforms them all. A stage along x stays inside its texel's tile (o = x mod n, read
// at the tile's origin + index); a stage along z reads its own column. The last stage may write
// one tile alone into an n × n target: uTileOrigin then says where that tile sits in the input.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uInput0;
uniform sampler2D uInput1;
uniform sampler2D uTwiddle;   // n × 1: (cos, sin) of 2π q/n
uniform int uN;
uniform int uHalfSize;        // Ns: the product of the radices of the stages before this one
uniform bool uVertical;       // false: along x (texel column), true: along z (texel row)
uniform int uTileOrigin;      // x of the tile the output's first column reads: 0 when writing the whole atlas

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

vec2 mul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

// Both complex values of an RGBA texel times the same complex w.
vec4 mul2(vec2 w, vec4 v) { return vec4(mul(w, v.xy), mul(w, v.zw)); }

// i·v for both complex values of a texel.
vec4 mulI2(vec4 v) { return vec4(-v.y, v.x, -v.w, v.z); }

// The input texel at `index` along the stage's axis, in the same tile and line as the output texel.
ivec2 along(ivec2 texel, int index) {
  int tileStart = uTileOrigin + (texel.x / uN) * uN;
  return uVertical ? ivec2(uTileOrigin + texel.x, index) : ivec2(tileStart + index, texel.y);
}

vec2 twiddle(int q) {
  return texelFetch(uTwiddle, ivec2(q, 0), 0).xy;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int o = uVertical ? texel.y : texel.x % uN;  // the index along the axis within the tile
  int k = o % uHalfSize;
#ifdef RADIX_4
  int j = (o / (4 * uHalfSize)) * uHalfSize + k;
  int r = (o / uHalfSize) % 4;
  int quarter = uN / 4;
  int step = k * uN / (4 * uHalfSize);  // θ = 2π·step/n
  vec2 w1 = twiddle(step);
  vec2 w2 = twiddle(2 * step);
  vec2 w3 = twiddle(3 * step);
  ivec2 i0 = along(texel, j);
  ivec2 i1 = along(texel, j + quarter);
  ivec2 i2 = along(texel, j + 2 * quarter);
  ivec2 i3 = along(texel, j + 3 * quarter);
  // v_m = e^{imθ} in[j + m n/4], then the 4-point inverse DFT's row r: Σ_m i^{m r} v_m.
  vec4 a0 = texelFetch(uInput0, i0, 0);
  vec4 b0 = mul2(w1, texelFetch(uInput0, i1, 0));
  vec4 c0 = mul2(w2, texelFetch(uInput0, i2, 0));
  vec4 d0 = mul2(w3, texelFetch(uInput0, i3, 0));
  vec4 a1 = texelFetch(uInput1, i0, 0);
  vec4 b1 = mul2(w1, texelFetch(uInput1, i1, 0));
  vec4 c1 = mul2(w2, texelFetch(uInput1, i2, 0));
  vec4 d1 = mul2(w3, texelFetch(uInput1, i3, 0));
  // Σ_m i^{mr} v_m = (a + i^{2r} c) + i^r (b + i^{2r} d), with i^{2r} = (−1)^r and
  // i^r = ±1 for even r, ±i for odd r (+ for r = 0, 1; − for r = 2, 3).
  float evenSign = (r % 2 == 0) ? 1.0 : -1.0;  // i^{2r}
  float rSign = r < 2 ? 1.0 : -1.0;
  vec4 ac0 = a0 + evenSign * c0;
  vec4 ac1 = a1 + evenSign * c1;
  vec4 bd0 = b0 + evenSign * d0;
  vec4 bd1 = b1 + evenSign * d1;
  vec4 t0 = (r % 2 == 0) ? bd0 : mulI2(bd0);
  vec4 t1 = (r % 2 == 0) ? bd1 : mulI2(bd1);
  out0 = ac0 + rSign * t0;
  out1 = ac1 + rSign * t1;
#else
  int j = (o / (2 * uHalfSize)) * uHalfSize + k;
  float sign = ((o / uHalfSize) % 2 == 0) ? 1.0 : -1.0;
  vec2 w = sign * twiddle(k * uN / (2 * uHalfSize));
  ivec2 ia = along(texel, j);
  ivec2 ib = along(texel, j + uN / 2);
  vec4 a0 = texelFetch(uInput0, ia, 0);
  vec4 b0 = texelFetch(uInput0, ib, 0);
  vec4 a1 = texelFetch(uInput1, ia, 0);
  vec4 b1 = texelFetch(uInput1, ib, 0);
  out0 = a0 + mul2(w, b0);
  out1 = a1 + mul2(w, b1);
#endif
}
