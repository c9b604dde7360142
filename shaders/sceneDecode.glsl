// The underwater passes' reading of the scene target (shaders/sceneEncode.glsl wrote it):
// the stored square root of the colour's share of SCENE_HEADROOM, back to linear colour.
vec3 sceneColor(vec4 stored) {
  return stored.rgb * stored.rgb * SCENE_HEADROOM;
}
