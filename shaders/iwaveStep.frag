// One time step of iWave (Tessendorf, "Interactive Water Surfaces", 2004): the GLSL twin of
// IWaveGrid.step in src/sim/iwave/iwaveGrid.ts (read the method there). Texel (i, j) holds
// (h now, h one step ago); the step writes (h next, h now) into the other target. Past the
// grid's edge the water reads as calm.
//   ∂²h/∂t² + α ∂h/∂t = −g √(−∇²) h,  √(−∇²)h ≈ (G ∗ h) / Δx,
// with G the 13 × 13 vertical-derivative kernel (src/sim/iwave/verticalDerivativeKernel.ts)
// and α the light damping plus the sponge along the border.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uHeights;   // n × n: (h, h⁻, ·, ·)
uniform sampler2D uKernel;    // (2R + 1)²: the weights, in r
uniform sampler2D uObstacle;  // n × n: 1 where water, 0 where solid, in r
uniform int uN;
uniform int uKernelRadius;
uniform float uKick;          // g Δt² / Δx
uniform float uDt;
uniform float uDamping;       // α everywhere, 1/s
uniform vec2 uSponge;         // (width in texels, α at the edge in 1/s)

out vec4 outHeights;

float heightAt(ivec2 p) {
  if (p.x < 0 || p.y < 0 || p.x >= uN || p.y >= uN) return 0.0;
  return texelFetch(uHeights, p, 0).r;
}

// spongeDamping in iwaveGrid.ts: rises as the square of the depth into the layer.
float spongeDamping(ivec2 p) {
  float fromEdge = float(min(min(p.x, uN - 1 - p.x), min(p.y, uN - 1 - p.y))) + 0.5;
  if (fromEdge >= uSponge.x) return 0.0;
  float depth = 1.0 - fromEdge / uSponge.x;
  return uSponge.y * depth * depth;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 now = texelFetch(uHeights, p, 0).rg;
  float convolved = 0.0;
  int size = 2 * uKernelRadius + 1;
  for (int b = 0; b < size; b++) {
    for (int a = 0; a < size; a++) {
      float w = texelFetch(uKernel, ivec2(a, b), 0).r;
      convolved += w * heightAt(p + ivec2(a - uKernelRadius, b - uKernelRadius));
    }
  }
  float half_ = 0.5 * (uDamping + spongeDamping(p)) * uDt;
  float next = (2.0 * now.x - (1.0 - half_) * now.y - uKick * convolved) / (1.0 + half_);
  next *= texelFetch(uObstacle, p, 0).r;
  outHeights = vec4(next, now.x, 0.0, 0.0);
}
