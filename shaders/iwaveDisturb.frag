// A disturbance: a Gaussian bump added at rest to h and h⁻ alike, the GLSL twin of
// IWaveGrid.disturb and bumpProfile in src/sim/iwave/iwaveGrid.ts.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D uHeights;   // n × n: (h, h⁻, ·, ·)
uniform sampler2D uObstacle;
uniform vec2 uCentre;         // the bump's centre in texel units (texel (i, j)'s centre is (i, j))
uniform float uRadius;        // texels
uniform float uHeight;        // metres
uniform float uReach;         // BUMP_REACH: radii past which the bump is cut

out vec4 outHeights;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 heights = texelFetch(uHeights, p, 0);
  float d = length(vec2(p) - uCentre);
  float bump = d >= uReach * uRadius ? 0.0 : uHeight * exp(-2.0 * d * d / (uRadius * uRadius));
  bump *= texelFetch(uObstacle, p, 0).r;
  outHeights = vec4(heights.rg + bump, heights.ba);
}
