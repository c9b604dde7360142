// Evaluates the ocean's displacement at arbitrary (x, z) points on the GPU: one point per
// output texel, so the CPU twin can be checked against the real shader code.
#include <oceano_displacement>

attribute vec2 aSample;
attribute float aIndex;
uniform vec2 uTargetSize;

varying vec4 vResult;

void main() {
  float height = oceanHeight(aSample);
  vec3 normal = oceanNormal(aSample, height);
  vResult = vec4(height, normal);
  vec2 texel = vec2(mod(aIndex, uTargetSize.x), floor(aIndex / uTargetSize.x)) + 0.5;
  gl_Position = vec4(texel / uTargetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
