// Evaluates the active wave model's chunk at arbitrary grid points (x, z) on the GPU, so
// the CPU twin can be checked against the real shader code. Two output texels per point:
// even index waveDisplacement (dx, dy, dz), odd index waveNormal; with the boat's wake on,
// both with the wake added exactly as ocean.vert adds it (at the displaced point).
#include <oceano_waves>
#include <oceano_wake>

attribute vec2 aSample;
attribute float aIndex;
uniform vec2 uTargetSize;

varying vec4 vResult;

void main() {
  bool normalTexel = mod(aIndex, 2.0) > 0.5;
  vec3 d = waveDisplacement(aSample);
  vec3 n = waveNormal(aSample);
  if (uWakeCount >= 2) {
    vec3 wake = wakeHeightAndGradient(aSample + d.xz);
    d.y += wake.x;
    n = wakeTiltNormal(n, wake.yz);
  }
  vResult = vec4(normalTexel ? n : d, 0.0);
  vec2 texel = vec2(mod(aIndex, uTargetSize.x), floor(aIndex / uTargetSize.x)) + 0.5;
  gl_Position = vec4(texel / uTargetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
