// One time step of iWave (Tessendorf, "Interactive Water Surfaces", 2004): the GLSL twin of
// IWaveGrid.step in src/sim/iwave/iwaveGrid.ts (read the method there). Texel (i, j) holds
// (h now, h one step ago); the step writes (h next, h now) into the other target. Past the
// grid's edge the water reads as calm.
//   ∂²h/∂t² + α ∂h/∂t = −g √(−∇²) h,  √(−∇²)h ≈ (G ∗ h) / Δx,
// with G the 13 × 13 vertical-derivative kernel (src/sim/iwave/verticalDerivativeKernel.ts)
// and α the light damping plus the sponge along the border. IWAVE_KERNEL_RADIUS and
// IWAVE_ORBITS are defined by GpuIWave from the TypeScript kernel.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uHeights;   // n × n: (h, h⁻, ·, ·)
uniform sampler2D uObstacle;  // n × n: 1 where water, 0 where solid, in r
// The kernel has the grid's eightfold symmetry: one weight per orbit (a, b), 0 ≤ b ≤ a ≤ R,
// listed a by a, b by b (kernelOrbitWeights). uRightWeights is the kernel of the texels right
// of the middle while uSplit is on (the wave equation beside iWave), a sponge lining the middle.
uniform float uWeights[IWAVE_ORBITS];
uniform float uRightWeights[IWAVE_ORBITS];
uniform bool uSplit;
uniform int uN;
uniform float uKick;          // g Δt² / Δx
uniform float uDt;
uniform float uDamping;       // α everywhere, 1/s
uniform vec2 uSponge;         // (width in texels, α at the edge in 1/s)
// The boat (src/sim/iwave/movingHull.ts), in texels: (centre, forward), (half length, half
// beam, source radius, source height this step in metres; half length 0: no boat), and its
// bow and stern sources' centres.
uniform vec4 uHull;
uniform vec4 uHullShape;
uniform vec4 uHullSources;
uniform float uReach;         // BUMP_REACH: radii past which a bump is cut

out vec4 outHeights;

float heightAt(ivec2 p) {
  if (p.x < 0 || p.y < 0 || p.x >= uN || p.y >= uN) return 0.0;
  return texelFetch(uHeights, p, 0).r;
}

float heightInside(ivec2 p) {
  return texelFetch(uHeights, p, 0).r;
}

// The sum of the kernel's taps over every orbit, each orbit's (up to) eight mirror images
// added before its one weight is applied. FETCH reads a height: checked near the edges only.
#define CONVOLVE(FETCH, W, result) { \
  result = W[0] * FETCH(p); \
  int o = 1; \
  for (int a = 1; a <= IWAVE_KERNEL_RADIUS; a++) { \
    for (int b = 0; b <= a; b++) { \
      float s = FETCH(p + ivec2(a, b)) + FETCH(p + ivec2(-b, a)) + FETCH(p + ivec2(-a, -b)) + FETCH(p + ivec2(b, -a)); \
      if (b > 0 && b < a) s += FETCH(p + ivec2(a, -b)) + FETCH(p + ivec2(b, a)) + FETCH(p + ivec2(-a, b)) + FETCH(p + ivec2(-b, -a)); \
      result += W[o] * s; \
      o++; \
    } \
  } \
}

// spongeDamping in iwaveGrid.ts: rises as the square of the depth into the layer; split, a
// layer half as wide lines the middle too.
float spongeDamping(ivec2 p) {
  float fromEdge = float(min(min(p.x, uN - 1 - p.x), min(p.y, uN - 1 - p.y))) + 0.5;
  float depth = max(1.0 - fromEdge / uSponge.x, 0.0);
  if (uSplit) depth = max(depth, 1.0 - abs(float(p.x) + 0.5 - 0.5 * float(uN)) / (0.5 * uSponge.x));
  return uSponge.y * depth * depth;
}

// hullCovers in movingHull.ts: 0 inside the waterline's ellipse.
float hullMask(vec2 p) {
  if (uHullShape.x == 0.0) return 1.0;
  vec2 d = p - uHull.xy;
  float along = dot(d, uHull.zw) / uHullShape.x;
  float across = dot(d, vec2(-uHull.w, uHull.z)) / uHullShape.y;
  return along * along + across * across <= 1.0 ? 0.0 : 1.0;
}

// A bump of bumpProfile's shape, cut at uReach radii.
float bump(vec2 p, vec2 centre, float radius) {
  vec2 d = p - centre;
  float r2 = dot(d, d);
  return r2 >= uReach * uReach * radius * radius ? 0.0 : exp(-2.0 * r2 / (radius * radius));
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 now = texelFetch(uHeights, p, 0).rg;
  float convolved;
  bool inside = all(greaterThanEqual(p, ivec2(IWAVE_KERNEL_RADIUS))) && all(lessThan(p, ivec2(uN - IWAVE_KERNEL_RADIUS)));
  bool right = uSplit && p.x >= uN / 2;
  if (right) {
    if (inside) CONVOLVE(heightInside, uRightWeights, convolved)
    else CONVOLVE(heightAt, uRightWeights, convolved)
  } else {
    if (inside) CONVOLVE(heightInside, uWeights, convolved)
    else CONVOLVE(heightAt, uWeights, convolved)
  }
  float half_ = 0.5 * (uDamping + spongeDamping(p)) * uDt;
  float next = (2.0 * now.x - (1.0 - half_) * now.y - uKick * convolved) / (1.0 + half_);
  vec2 q = vec2(p);
  float mask = texelFetch(uObstacle, p, 0).r * hullMask(q);
  // The hull's sources, added at rest (to h and h⁻ alike) after the step.
  float source = 0.0;
  if (uHullShape.x > 0.0) source = uHullShape.w * (bump(q, uHullSources.xy, uHullShape.z) - bump(q, uHullSources.zw, uHullShape.z)) * mask;
  outHeights = vec4(next * mask + source, now.x + source, 0.0, 0.0);
}
