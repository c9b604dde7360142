// Appended to three.js's colorspace_fragment (src/render/sceneEncoding.ts), so it ends every
// material's shader, ours and three's (the boat's). When the scene is drawn for the underwater
// passes, OCEANO_SCENE_HEADROOM is defined on its materials: the linear colour is stored in an
// RGBA8 target as the square root of its share of the headroom. SwiftShader writes and reads
// 8-bit targets far faster than half floats; the square root spends the 8 bits about as the
// output's sRGB levels do, so the dark water does not band; the headroom keeps highlights
// that the water fog will dim (the sun's glint seen from below) from clipping before it does.
#ifdef OCEANO_SCENE_HEADROOM
gl_FragColor.rgb = sqrt(clamp(gl_FragColor.rgb * (1.0 / OCEANO_SCENE_HEADROOM), 0.0, 1.0));
#endif
