// The foam the smallest cascade remembers, one step of the lattice of simulation times
// (src/sim/waves/fft/foamMemory.ts: never per frame, so playing, stepping and jumping draw the
// same foam). Per texel of its tile: the older potential faded by e^{−Δ/τ}, or the fresh one
// where the cascade breaks now, the larger; a potential faded below sight is forgotten
// (rememberFoam, the TS twin). The fresh potential is 1 at the cascade's breaking threshold
// and grows into the fold, up to FOAM_POTENTIAL_MAX: a deeper fold leaves foam that lasts longer.
// The older foam is read uDrift texels upstream: the surface's wind drift carries it, by whole
// texels (src/sim/waves/fft/foamDrift.ts; driftedMemoryStep is the TS twin of this pass).
// FOAM_POTENTIAL_MAX and FOAM_POTENTIAL_VISIBLE are defined from TypeScript (fftFoam.ts).
precision highp float;
precision highp int;
precision highp sampler2D;

#include <oceano_fft_breaking>

uniform sampler2D uDisplacement;   // the smallest cascade at the lattice time: (dx, dy, dz, ∂Dx/∂x)
uniform sampler2D uDerivatives;    // (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
uniform sampler2D uPrevious;       // r: the potential at the previous lattice time
uniform ivec2 uDrift;              // texels the memory moves in this step (x, z)
uniform float uDecay;              // e^{−Δ/τ}, or 0 to start from nothing
uniform float uThreshold;          // this cascade's breaking threshold
uniform float uSoftness;           // the potential's unit: how far below the threshold one more is

out vec4 outMemory;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float jxx = texelFetch(uDisplacement, texel, 0).w;
  vec4 d = texelFetch(uDerivatives, texel, 0);
  float fresh = clamp((uThreshold - fftBreaking(jxx, d.z, d.w)) / uSoftness + 1.0, 0.0, FOAM_POTENTIAL_MAX);
  ivec2 n = textureSize(uPrevious, 0);
  ivec2 upstream = ((texel - uDrift) % n + n) % n;
  float potential = max(texelFetch(uPrevious, upstream, 0).r * uDecay, fresh);
  outMemory = vec4(potential < FOAM_POTENTIAL_VISIBLE ? 0.0 : potential, 0.0, 0.0, 1.0);
}
