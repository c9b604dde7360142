// Time evolution of the cascades' spectra, the GPU half of src/sim/waves/fft/spectralFields.ts,
// in one pass over an atlas of n × n tiles side by side along x (src/render/waves/fft/gpuFft.ts):
// each tile has its own time and tile size and reads the h₀ of one cascade (two tiles may read
// the same cascade at two times: the foam's lattice time beside the frame's). Per texel:
// h̃(k,t) = h₀(k) e^{iωt} + conj(h₀(−k)) e^{−iωt} (Tessendorf 2001, eq. 26), then the eight
// fields packed two real fields per complex number (see spectralFields.ts for the signs):
//   out0 = (Dx + i h,      Dz + i ∂xDx)      out1 = (∂xh + i ∂zh,   ∂zDz + i ∂xDz)
// Time enters only as τ/T ∈ [0, 1) with ω = m·2π/T quantised (m a whole number; Tessendorf
// §3.2.1), and the phase is 2π·fract(m·τ/T). A float32 τ/T alone would cost m·τ/T·6e-8 cycles
// (1e-3 rad for m = 10⁴), so τ/T comes split in three, t1 + t2 + t3 (12 bits, 12 bits, rest),
// and m in two, 4096·mh + ml (12 bits each): every partial product below is exact in float32.
precision highp float;
precision highp int;
precision highp sampler2D;

// The driver's cos and sin may be approximations good to only ~1e-4 (SwiftShader's are).
#include <oceano_sin_turns>

// TILES (the atlas's tiles) is defined from TypeScript.
uniform sampler2D uH0;       // per cascade's tile: (Re h₀(k), Im h₀(k), Re h₀(−k), Im h₀(−k))
uniform sampler2D uCycles;   // (4096·mh, ml, m): m = ω/ω₀ = 4096·mh + ml, whole cycles per repeat period T
uniform int uCascade[TILES];       // per atlas tile: the cascade (tile of uH0, uCycles) it evolves
uniform vec3 uTauOverT[TILES];     // (t mod T) / T = x + y + z, reduced and split in float64 on the CPU
uniform float uTileSize[TILES];    // L, m
uniform float uChoppiness;   // λ
uniform int uN;

layout(location = 0) out vec4 outDisplacement;
layout(location = 1) out vec4 outDerivatives;

vec2 mulI(vec2 z) { return vec2(-z.y, z.x); }

void main() {
  ivec2 atlasTexel = ivec2(gl_FragCoord.xy);
  int tile = atlasTexel.x / uN;
  ivec2 texel = ivec2(atlasTexel.x - tile * uN, atlasTexel.y);  // (a, b) within the tile
  ivec2 spectrumTexel = ivec2(uCascade[tile] * uN + texel.x, texel.y);
  vec4 h0 = texelFetch(uH0, spectrumTexel, 0);
  vec3 m = texelFetch(uCycles, spectrumTexel, 0).rgb;
  vec3 t = uTauOverT[tile];
  float cycles = fract(m.x * t.x) + fract(m.x * t.y) + fract(m.y * t.x) + fract(m.y * t.y) + m.z * t.z;
  // Reduced first, so that cosTurns' quarter turn is added to a number below 1.
  float turns = fract(cycles);
  float c = cosTurns(turns);
  float s = sinTurns(turns);
  // h₀(k) e^{iφ} + conj(h₀(−k)) e^{−iφ}
  vec2 a = vec2(h0.x * c - h0.y * s, h0.x * s + h0.y * c);
  vec2 b = vec2(h0.z * c - h0.w * s, -(h0.z * s + h0.w * c));
  vec2 h = a + b;

  ivec2 signedIndex = texel - ivec2(greaterThanEqual(texel, ivec2(uN / 2))) * uN;
  vec2 k = vec2(signedIndex) * (TURN_RADIANS / uTileSize[tile]);
  float kLength = length(k);
  vec2 u = kLength > 0.0 ? k / kLength : vec2(0.0);

  vec2 ih = mulI(h);
  vec2 dx = uChoppiness * u.x * ih;
  vec2 dz = uChoppiness * u.y * ih;
  vec2 dxdx = -uChoppiness * k.x * u.x * h;
  vec2 dzdz = -uChoppiness * k.y * u.y * h;
  vec2 dxdz = -uChoppiness * k.x * u.y * h;
  vec2 sx = k.x * ih;
  vec2 sz = k.y * ih;
  outDisplacement = vec4(dx + mulI(h), dz + mulI(dxdx));
  outDerivatives = vec4(sx + mulI(sz), dzdz + mulI(dxdz));
}
