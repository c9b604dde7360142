// The underwater passes' reading of the scene target. Encoded (shaders/sceneEncode.glsl wrote
// it): the square root below SCENE_LOW_SHARE, the logarithmic shoulder above, back to linear
// colour. A half-float target (OCEANO_SCENE_LINEAR) holds linear colour as it is.
vec3 sceneColor(vec4 stored) {
#ifdef OCEANO_SCENE_LINEAR
  return stored.rgb;
#else
  vec3 low = stored.rgb / SCENE_LOW_SHARE;
  vec3 high = exp2((stored.rgb - SCENE_LOW_SHARE) / (1.0 - SCENE_LOW_SHARE) * log2(SCENE_BRIGHTEST));
  return mix(low * low, high, step(SCENE_LOW_SHARE + 0.5 / 255.0, stored.rgb));
#endif
}
