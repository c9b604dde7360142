// A full-screen pass's line of sight: from the eye through the pixel's point on the near
// plane, as far as the depth buffer says the scene lies. Needs <packing> first.

uniform mat4 uProjectionInverse;
uniform mat4 uCameraWorld;
uniform vec3 uEye;
uniform float uNear;
uniform float uFar;

// The pixel's point on the near plane in view space (w = 1); ndc in [-1, 1]².
vec4 nearViewPoint(vec2 ndc) {
  vec4 p = uProjectionInverse * vec4(ndc, -1.0, 1.0);
  return p / p.w;
}

vec3 nearWorldPoint(vec4 nearView) {
  return (uCameraWorld * nearView).xyz;
}

// Metres from the eye to what the depth buffer holds along the line through nearView;
// 1e6 where nothing was drawn (the far plane).
float sightDistance(vec4 nearView, float depthSample) {
  if (depthSample >= 1.0) return 1e6;
  float viewZ = perspectiveDepthToViewZ(depthSample, uNear, uFar);
  return length(nearView.xyz * (viewZ / nearView.z));
}
