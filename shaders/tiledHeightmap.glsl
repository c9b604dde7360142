// A square heightmap tiled over the plane, sampled bilinearly by hand. Shared by the seed
// waves' ripples and the sea bed's mottling; included by each, hence the guard.
#ifndef OCEANO_TILED_HEIGHTMAP
#define OCEANO_TILED_HEIGHTMAP

// p reduced to one tile without rounding: tile * floor(p / tile) is a multiple of the tile
// that float32 holds exactly, and p minus it is exact too (the difference is smaller than p
// and on p's own lattice). fract(p / tile) instead rounds p / tile to float32 first, which
// far from the origin moves the sample by about |p| · 6e-8 m and shows in the heights.
vec2 wrapToTile(vec2 p, float tileSize) {
  return p - tileSize * floor(p / tileSize);
}

// Bilinear with wrap by hand: texel (i, j) sits at world offset (i, j) * tile / size.
// Each texel holds its own height and those of its +x, +z and diagonal neighbours
// (wrapped; see gatheredHeightmap in src/render/optics/dataTextures.ts), so one fetch gives the
// four corners and no modulo is needed. The offset is added after the point is brought
// into its tile, where the sum rounds at small magnitude.
float sampleTiledHeightmap(sampler2D map, vec2 p, vec2 offset, float tileSize, float mapSize) {
  vec2 st = fract((wrapToTile(p, tileSize) + offset) / tileSize) * mapSize;
  vec2 cell = floor(st);
  vec2 f = st - cell;
  vec4 corners = texelFetch(map, ivec2(cell), 0);
  return mix(mix(corners.x, corners.y, f.x), mix(corners.z, corners.w, f.x), f.y);
}

#endif
