import { DataTexture, FloatType, NearestFilter, RedFormat, RepeatWrapping, ClampToEdgeWrapping } from 'three';
import type { Heightmap } from '../sim/perlinNoise';

/** Single-channel float texture read with texelFetch; filtering is done in the shaders. */
function floatTexture(data: Float32Array, width: number, height: number, wrap: typeof RepeatWrapping | typeof ClampToEdgeWrapping): DataTexture {
  const texture = new DataTexture(data, width, height, RedFormat, FloatType);
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.wrapS = wrap;
  texture.wrapT = wrap;
  texture.generateMipmaps = false;
  texture.needsUpdate = true;
  return texture;
}

export function heightmapTexture(map: Heightmap): DataTexture {
  return floatTexture(map.data, map.size, map.size, RepeatWrapping);
}

export function fresnelTexture(table: Float32Array): DataTexture {
  return floatTexture(table, table.length, 1, ClampToEdgeWrapping);
}
