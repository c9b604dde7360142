// Evaluates the active wave model's chunk at arbitrary grid points (x, z) on the GPU, so
// the CPU twin can be checked against the real shader code. Two output texels per point:
// even index waveDisplacement (dx, dy, dz), odd index waveNormal; with the boat's wake on,
// both with the wake added exactly as ocean.vert adds it (at the displaced point), and with
// the interactive waves on, their field too, the two weighted by the hand-over as there.
// The normal texel's w: on the spectral sea, the windrows' share of the foam left behind at
// the grid point (shaders/foam/foamWindrows.glsl, compiled in here at every wind), for the
// parity check of windrowShare (src/sim/waves/fft/windrows.ts); 0 on the other seas.
#include <oceano_waves>
#include <oceano_wake>
#ifdef OCEAN_IWAVE
#include <oceano_iwave>
#endif
#ifdef OCEAN_COAST
#include <oceano_coast>
#endif

attribute vec2 aSample;
attribute float aIndex;
uniform vec2 uTargetSize;

varying vec4 vResult;

void main() {
  bool normalTexel = mod(aIndex, 2.0) > 0.5;
  vec3 d = waveDisplacement(aSample);
  vec3 n = waveNormal(aSample);
#ifdef OCEAN_COAST
  // The coast as ocean.vert adds it: the wind sea (off: none) calmed by the depth at its grid point, plus the swell where it lands.
  float windFactor = coastWindFactor(aSample);
  d *= windFactor;
  CoastSwell swell = coastSwellAt(aSample + d.xz);
  d.y += swell.height;
  n = coastTiltNormal(n, windFactor, swell.slope);
#endif
  vec2 at = aSample + d.xz;
#ifdef OCEAN_IWAVE
  vec2 handOver = iwaveHandOver(at, vec2(0.0));
#else
  const vec2 handOver = vec2(1.0);
#endif
  if (uWakeCount >= 2) {
    vec3 wake = handOver.x * wakeHeightAndGradient(at);
    d.y += wake.x;
    n = wakeTiltNormal(n, wake.yz);
  }
#ifdef OCEAN_IWAVE
  vec3 field = handOver.y * iwaveHeightAndGradient(at, vec2(0.0));
  d.y += field.x;
  n = wakeTiltNormal(n, field.yz);
#endif
#ifdef WAVE_FOAM
  float windrows = foamWindrowShare(aSample, false, 0.0);
#else
  const float windrows = 0.0;
#endif
  vResult = normalTexel ? vec4(n, windrows) : vec4(d, 0.0);
  vec2 texel = vec2(mod(aIndex, uTargetSize.x), floor(aIndex / uTargetSize.x)) + 0.5;
  gl_Position = vec4(texel / uTargetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
