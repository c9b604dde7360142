// Foam of each cascade, accumulated in its own texture (the texel grid of its FFT tile):
// where the choppy displacement folds or nearly folds, the Jacobian J of the horizontal map
// x ↦ x + D(x) drops below a threshold (Tessendorf 2001, §4.3: J < 0 where crests loop), and
// foam appears; elsewhere the foam already there fades as e^{−Δt/τ}. r = foam, g = this
// cascade's J (for inspection), b = this cascade's ∂Dx/∂x, copied so that the ocean's pixels
// find everything they need in this texture and the derivatives one, two filtered reads per
// cascade instead of three (shaders/waves/fft.glsl). r is a foam potential, 1 at the
// threshold: the ocean draws the smallest cascade's as foam left behind from r = 1.25 on.
// One draw steps all three cascades (three colour attachments, MRT).
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uDisplacement0;  // per cascade: (dx, dy, dz, ∂Dx/∂x)
uniform sampler2D uDisplacement1;
uniform sampler2D uDisplacement2;
uniform sampler2D uDerivatives0;   // per cascade: (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
uniform sampler2D uDerivatives1;
uniform sampler2D uDerivatives2;
uniform sampler2D uPrevious0;      // per cascade, r: foam at the previous step
uniform sampler2D uPrevious1;
uniform sampler2D uPrevious2;
uniform float uDecay;              // e^{−Δt/τ}
uniform vec3 uThreshold;           // each cascade's Jacobian threshold
uniform vec3 uSoftness;            // half-width of the edge around it (a fraction of J's spread)

layout(location = 0) out vec4 outFoam0;
layout(location = 1) out vec4 outFoam1;
layout(location = 2) out vec4 outFoam2;

vec4 foamStep(sampler2D displacement, sampler2D derivatives, sampler2D previous, float threshold, float softness, ivec2 texel) {
  float jxx = texelFetch(displacement, texel, 0).w;
  vec4 d = texelFetch(derivatives, texel, 0);
  float jacobian = (1.0 + jxx) * (1.0 + d.z) - d.w * d.w;
  // Stored is not the foam but how far J went past the threshold, in units of the edge's
  // half-width: 0 at threshold + 1 edge and above, 1 at the threshold, growing into the fold.
  // Linear in J, so the ocean shader's bilinear read draws a smooth edge (foam/white at ≥ 1),
  // not the texel squares a thresholded value gives; kept while it fades.
  float fresh = clamp((threshold - jacobian) / softness + 1.0, 0.0, 4.0);
  float old = texelFetch(previous, texel, 0).r * uDecay;
  return vec4(max(old, fresh), jacobian, jxx, 1.0);
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  outFoam0 = foamStep(uDisplacement0, uDerivatives0, uPrevious0, uThreshold.x, uSoftness.x, texel);
  outFoam1 = foamStep(uDisplacement1, uDerivatives1, uPrevious1, uThreshold.y, uSoftness.y, texel);
  outFoam2 = foamStep(uDisplacement2, uDerivatives2, uPrevious2, uThreshold.z, uSoftness.z, texel);
}
