// A small square around the sun's disc, drawn over the sky (src/render/sky/sunDiscSprite.ts), so
// that only the pixels near the disc pay for its antialiased edge (skyBackground.frag,
// OCEANO_DISC_THROUGH_ROLL_OFF). Where it lies on the screen is worked out on the CPU.

uniform mat4 uClipToWorldDirection;
uniform vec2 uDiscCentre;    // the sun's place in normalised device coordinates
uniform vec2 uDiscHalfSize;  // the square's half size there
varying vec3 vRay;

void main() {
  vec2 corner = uDiscCentre + position.xy * uDiscHalfSize;
  // At the far plane, as the sky: whatever else is drawn lies in front.
  gl_Position = vec4(corner, 1.0, 1.0);
  vRay = (uClipToWorldDirection * vec4(corner, 1.0, 1.0)).xyz;
}
