// What the ocean's pixels read of each cascade besides its derivatives (shaders/waves/fft.glsl),
// packed every frame into one texture per cascade so that a pixel makes two filtered reads per
// cascade instead of three: r = the foam the smallest cascade remembers, faded from the last
// lattice time to now (shaders/fftFoamMemory.frag; 0 in the other cascades), b = ∂Dx/∂x.
// The memory is smoothed over 3 × 3 texels (binomial weights) as it is packed: it is a max of
// thresholded deposits, and read bilinearly as it is, its patches came out as the texels' squares.
// One draw packs all three cascades (three colour attachments, MRT).
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uDisplacement0;  // per cascade: (dx, dy, dz, ∂Dx/∂x)
uniform sampler2D uDisplacement1;
uniform sampler2D uDisplacement2;
uniform sampler2D uMemory;         // r: the smallest cascade's remembered potential
uniform float uFade;               // e^{−(t − t_k)/τ} since the last lattice time t_k (0: no foam)

layout(location = 0) out vec4 outFoam0;
layout(location = 1) out vec4 outFoam1;
layout(location = 2) out vec4 outFoam2;

float smoothedMemory(ivec2 texel) {
  int n = textureSize(uMemory, 0).x;
  float sum = 0.0;
  for (int j = -1; j <= 1; j++) {
    for (int i = -1; i <= 1; i++) {
      float weight = (2.0 - abs(float(i))) * (2.0 - abs(float(j)));
      sum += weight * texelFetch(uMemory, (texel + ivec2(i, j) + n) % n, 0).r;
    }
  }
  return sum / 16.0;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  outFoam0 = vec4(0.0, 0.0, texelFetch(uDisplacement0, texel, 0).w, 1.0);
  outFoam1 = vec4(0.0, 0.0, texelFetch(uDisplacement1, texel, 0).w, 1.0);
  outFoam2 = vec4(smoothedMemory(texel) * uFade, 0.0, texelFetch(uDisplacement2, texel, 0).w, 1.0);
}
