// Foam of one cascade, accumulated in its own texture (the texel grid of its FFT tile):
// where the choppy displacement folds or nearly folds, the Jacobian J of the horizontal map
// x ↦ x + D(x) drops below a threshold (Tessendorf 2001, §4.3: J < 0 where crests loop), and
// foam appears; elsewhere the foam already there fades as e^{−Δt/τ}. r = foam, g = this
// cascade's J (for inspection), b = this cascade's ∂Dx/∂x, copied so that the ocean's pixels
// find everything they need in this texture and the derivatives one, two filtered reads per
// cascade instead of three (shaders/waves/fft.glsl). r is a foam potential: the shader draws
// foam where r ≥ ~1.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uDisplacement;  // (dx, dy, dz, ∂Dx/∂x)
uniform sampler2D uDerivatives;   // (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
uniform sampler2D uPrevious;      // r: foam at the previous step
uniform float uDecay;             // e^{−Δt/τ}
uniform float uThreshold;         // this cascade's Jacobian threshold
uniform float uSoftness;          // half-width of the edge around it (a fraction of J's spread)

layout(location = 0) out vec4 outFoam;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float jxx = texelFetch(uDisplacement, texel, 0).w;
  vec4 d = texelFetch(uDerivatives, texel, 0);
  float jacobian = (1.0 + jxx) * (1.0 + d.z) - d.w * d.w;
  // Stored is not the foam but how far J went past the threshold, in units of the edge's
  // half-width: 0 at threshold + 1 edge and above, 1 at the threshold, growing into the fold.
  // Linear in J, so the ocean shader's bilinear read draws a smooth edge (foam/white at ≥ 1),
  // not the texel squares a thresholded value gives; kept while it fades.
  float fresh = clamp((uThreshold - jacobian) / uSoftness + 1.0, 0.0, 4.0);
  float old = texelFetch(uPrevious, texel, 0).r * uDecay;
  outFoam = vec4(max(old, fresh), jacobian, jxx, 1.0);
}
