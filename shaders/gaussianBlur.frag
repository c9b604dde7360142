// One direction of a separable Gaussian blur at half resolution (or, with ONE_PASS, a blur
// within 1 texel in both directions), on premultiplied colour:
// the water pass writes (colour, 1) where the line of sight starts in the water and
// (0, 0, 0, 0) where it starts in the air, so air pixels add nothing and the blurred alpha
// is the share of water under the kernel (the composite divides by it). Premultiplied,
// every tap is linear in the texels, so pairs of texels are read as one bilinear tap
// (src/render/underwater/gaussianKernel.ts: linearSampledKernel) and the sum is still the exact Gaussian.

#include <oceano_constants>
#ifdef OCEANO_TONE_MAPPING
// three.js's tone-mapping functions, which it leaves out of a pass into a render target.
#include <tonemapping_pars_fragment>
#endif

uniform sampler2D tDiffuse;
uniform vec2 uStep;
uniform float uOffsets[BLUR_MAX_TAPS];
uniform float uWeights[BLUR_MAX_TAPS];
uniform int uTaps;

varying vec2 vUv;

void main() {
#ifdef ONE_PASS
  // Both directions at once for a kernel within 1 texel (src/render/underwater/gaussianKernel.ts,
  // onePassBlurOffset): four bilinear taps at (±o, ±o), uStep being (o / width, o / height).
  vec4 sum = 0.25 * (texture2D(tDiffuse, vUv + uStep) + texture2D(tDiffuse, vUv - uStep)
    + texture2D(tDiffuse, vUv + vec2(uStep.x, -uStep.y)) + texture2D(tDiffuse, vUv - vec2(uStep.x, -uStep.y)));
#else
  vec4 sum = uWeights[0] * texture2D(tDiffuse, vUv);
  for (int i = 1; i < BLUR_MAX_TAPS; i++) {
    if (i >= uTaps) break;
    vec2 offset = uStep * uOffsets[i];
    sum += uWeights[i] * (texture2D(tDiffuse, vUv + offset) + texture2D(tDiffuse, vUv - offset));
  }
#endif
#ifdef ENCODE_OUTPUT
  // The last pass, into RGBA8 for the composite: the water colour already as the canvas will
  // hold it (through the renderer's tone curve, OCEANO_TONE_MAPPING naming its function, then
  // sRGB, clipped at 1 as the canvas clips it), premultiplied again so that the composite's
  // bilinear upsample still weighs each texel by its share of water. The composite then only
  // divides: the curve and the encoding ran for every canvas pixel there, four times as many as here.
  vec3 water = sum.rgb / max(sum.a, 1e-6);
#ifdef OCEANO_TONE_MAPPING
  water = OCEANO_TONE_MAPPING(water);
#endif
  water = clamp(water, 0.0, 1.0);
  gl_FragColor = vec4(sRGBTransferOETF(vec4(water, 1.0)).rgb * sum.a, sum.a);
#else
  gl_FragColor = sum;
#endif
}
