// Time evolution of one cascade's spectrum, the GPU half of src/sim/waves/fft/spectralFields.ts:
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

uniform sampler2D uH0;       // (Re h₀(k), Im h₀(k), Re h₀(−k), Im h₀(−k))
uniform sampler2D uCycles;   // (4096·mh, ml, m): m = ω/ω₀ = 4096·mh + ml, whole cycles per repeat period T
uniform vec3 uTauOverT;      // (t mod T) / T = x + y + z, reduced and split in float64 on the CPU
uniform float uTileSize;     // L, m
uniform float uChoppiness;   // λ
uniform int uN;

layout(location = 0) out vec4 outDisplacement;
layout(location = 1) out vec4 outDerivatives;

vec2 mulI(vec2 z) { return vec2(-z.y, z.x); }

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 h0 = texelFetch(uH0, texel, 0);
  vec3 m = texelFetch(uCycles, texel, 0).rgb;
  vec3 t = uTauOverT;
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
  vec2 k = vec2(signedIndex) * (TURN_RADIANS / uTileSize);
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
