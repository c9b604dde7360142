// Appended to three.js's colorspace_fragment (src/render/underwater/sceneEncoding.ts), so it ends every
// material's shader, ours and three's (the boat's). While the scene is drawn for the underwater
// passes, OCEANO_SCENE_ENCODE is defined on its materials and the linear colour is stored in an
// RGBA8 target (perf: for the software rasterizer, docs/shader-notes.md): up to
// 1, its square root in the codes below SCENE_LOW_SHARE, which spends them about as the
// output's sRGB levels do, so neither the dark water nor the sky seen through the waterline
// bands; from 1 to SCENE_BRIGHTEST, a logarithmic shoulder in the codes above, for highlights
// the water fog will dim before the output clips them (the sun seen from below).
#ifdef OCEANO_SCENE_ENCODE
{
  vec3 c = max(gl_FragColor.rgb, 0.0);
  gl_FragColor.rgb = sqrt(min(c, 1.0)) * SCENE_LOW_SHARE
    + (1.0 - SCENE_LOW_SHARE) * log2(clamp(c, 1.0, SCENE_BRIGHTEST)) / log2(SCENE_BRIGHTEST);
}
#endif
