// One direction of a separable Gaussian blur. Only pixels whose line of sight starts in
// the water (alpha = 1, written by the underwater pass) are blurred, and only with each
// other, so a waterline across the screen stays sharp on the air side.

#include <oceano_constants>

uniform sampler2D tDiffuse;
uniform vec2 uStep;
uniform float uWeights[BLUR_MAX_RADIUS + 1];
uniform int uRadius;
// The last pass that needs the mask makes the frame opaque again for the canvas.
uniform bool uLastMaskUse;

varying vec2 vUv;

void main() {
  vec4 center = texture2D(tDiffuse, vUv);
  vec3 sum = center.rgb * (uWeights[0] * center.a);
  float total = uWeights[0] * center.a;
  for (int i = 1; i <= BLUR_MAX_RADIUS; i++) {
    if (i > uRadius) break;
    vec2 offset = uStep * float(i);
    vec4 a = texture2D(tDiffuse, vUv + offset);
    vec4 b = texture2D(tDiffuse, vUv - offset);
    sum += uWeights[i] * (a.rgb * a.a + b.rgb * b.a);
    total += uWeights[i] * (a.a + b.a);
  }
  vec3 blurred = total > 0.0 ? sum / total : center.rgb;
  gl_FragColor = vec4(mix(center.rgb, blurred, center.a), uLastMaskUse ? 1.0 : center.a);
}
