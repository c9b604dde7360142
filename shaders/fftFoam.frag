// Foam of one cascade, accumulated in its own texture (the texel grid of its FFT tile):
// where the choppy displacement folds or nearly folds, the Jacobian J of the horizontal map
// x ↦ x + D(x) drops below a threshold (Tessendorf 2001, §4.3: J < 0 where crests loop), and
// foam appears; elsewhere the foam already there fades as e^{−Δt/τ}. r = foam, g = this
// cascade's J (for inspection).
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uDisplacement;  // (dx, dy, dz, ∂Dx/∂x)
uniform sampler2D uDerivatives;   // (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
uniform sampler2D uPrevious;      // r: foam at the previous step
uniform float uDecay;             // e^{−Δt/τ}
uniform float uThreshold;

layout(location = 0) out vec4 outFoam;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float jxx = texelFetch(uDisplacement, texel, 0).w;
  vec4 d = texelFetch(uDerivatives, texel, 0);
  float jacobian = (1.0 + jxx) * (1.0 + d.z) - d.w * d.w;
  float fresh = clamp((uThreshold - jacobian) * 12.0, 0.0, 1.0);
  float old = texelFetch(uPrevious, texel, 0).r * uDecay;
  outFoam = vec4(max(old, fresh), jacobian, 0.0, 1.0);
}
