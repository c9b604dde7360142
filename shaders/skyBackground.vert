// The sky behind everything, as one triangle covering the screen: each pixel's view ray is
// the inverse of the camera's projection at that pixel, exact and never degenerate. (three's
// own background box puts its corners in the camera's plane when the camera looks level
// along a 45° diagonal; the divide by w = 0 then smeared one sky colour over whole triangles.)

uniform mat4 uClipToWorldDirection;
varying vec3 vRay;
varying vec2 vClip;

void main() {
  // At the far plane (depth 1): whatever else is drawn lies in front.
  gl_Position = vec4(position.xy, 1.0, 1.0);
  vec4 far = uClipToWorldDirection * vec4(position.xy, 1.0, 1.0);
  vRay = far.xyz;
  vClip = position.xy;
}
