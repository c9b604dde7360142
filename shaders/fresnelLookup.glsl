#ifndef OCEANO_FRESNEL_LOOKUP
#define OCEANO_FRESNEL_LOOKUP
// The exact Fresnel reflectance read from its table (src/sim/optics/fresnel.ts fresnelTable).
// Linear interpolation between table entries done by hand: float textures are not
// filterable everywhere in WebGL2.
float fresnelLookup(sampler2D table, float cosIncidence) {
  int size = textureSize(table, 0).x;
  float x = clamp(cosIncidence, 0.0, 1.0) * float(size - 1);
  int i = int(floor(x));
  int j = min(i + 1, size - 1);
  float a = texelFetch(table, ivec2(i, 0), 0).r;
  float b = texelFetch(table, ivec2(j, 0), 0).r;
  return mix(a, b, x - float(i));
}
#endif
