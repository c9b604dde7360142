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

vec3 skyCubeColor(vec3 direction) {
  vec3 stored = texture(uSky, vec3(uSkyFlip * direction.x, direction.y, direction.z)).rgb;
  return mix(stored, stored * stored, uSkySquared);
}

#endif
