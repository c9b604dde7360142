// The sky cube as every shader reads it. The default sky's cube (src/render/sky/sunSky.ts) holds
// the square root of the linear colour in 8 bits a channel (perf: RGBA8 rather than half
// floats, for the software rasterizer, docs/shader-notes.md): the square root spends the 8 bits
// where the eye sees them, steps of about one output level, as sRGB does. Cubes made from
// images are sRGB textures the hardware decodes: uSkySquared is 0 for them.
#ifndef OCEANO_SKY_CUBE
#define OCEANO_SKY_CUBE

uniform samplerCube uSky;
// -1 for a cube map made from images (three mirrors those in x), +1 for a cube render target.
uniform float uSkyFlip;
// 1 where the cube holds the square root of the colour (skyDome.frag), 0 where it holds the colour.
uniform float uSkySquared;

// The cube's full resolution (level 0): where a 2×2 block of pixels straddles an edge, the
// directions they look up jump, and a level picked from their differences would blur the
// sky there (a dark dash along the horizon).
vec3 skyCubeColor(vec3 direction) {
  vec3 stored = textureLod(uSky, vec3(uSkyFlip * direction.x, direction.y, direction.z), 0.0).rgb;
  return mix(stored, stored * stored, uSkySquared);
}

// The sky in a rough mirror: facets of mean-square slope `variance` (both axes) tilt by
// √(variance / 2) per axis and turn the reflected ray by twice that, √(2 variance); the mip
// level whose box of texels spreads as far is read: a box w wide spreads w / √12, and a face
// of `size` texels spans π/2, so w = size √(24 variance) / (π/2) = size √(9.73 variance)
// texels, level log2 w. The two levels around it are blended here (perf: the cube is sampled
// from one level, LinearMipmapNearest, since SwiftShader's own trilinear filter cost more than
// two reads, docs/light.md). The cube's mips are plain 2×2 means (src/render/sky/sunSky.ts), of
// square roots for the default sky: where the sky changes fast the mean comes out a little dark.
vec3 skyCubeColorRough(vec3 direction, float variance) {
  float lod = max(log2(float(textureSize(uSky, 0).x) * sqrt(9.73 * variance)), 0.0);
  vec3 d = vec3(uSkyFlip * direction.x, direction.y, direction.z);
  float level = floor(lod);
  vec3 stored = mix(textureLod(uSky, d, level).rgb, textureLod(uSky, d, level + 1.0).rgb, lod - level);
  return mix(stored, stored * stored, uSkySquared);
}

#endif
