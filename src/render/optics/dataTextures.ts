import { ClampToEdgeWrapping, DataTexture, FloatType, NearestFilter, RedFormat, RGBAFormat, RepeatWrapping } from 'three';
import type { Heightmap } from '../../sim/noise/perlinNoise';

/** A float texture read with texelFetch (unfiltered: the shaders interpolate by hand, as the CPU twins do). */
export function floatTexture(
  data: Float32Array,
  width: number,
  height: number,
  format: typeof RedFormat | typeof RGBAFormat,
  wrap: typeof RepeatWrapping | typeof ClampToEdgeWrapping,
): DataTexture {
  const texture = new DataTexture(data, width, height, format, FloatType);
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.wrapS = wrap;
  texture.wrapT = wrap;
  texture.generateMipmaps = false;
  texture.needsUpdate = true;
  return texture;
}

/**
 * The heightmap with each texel's 2×2 bilinear footprint gathered into RGBA: (i, j),
 * (i+1, j), (i, j+1), (i+1, j+1), wrapped. The values are the heightmap's own, so the
 * shader's bilinear sample equals the CPU twin's, with one texture fetch instead of four.
 */
export function gatheredHeightmap(map: Heightmap): Float32Array {
  const n = map.size;
  const out = new Float32Array(n * n * 4);
  for (let j = 0; j < n; j++) {
    const j1 = (j + 1) % n;
    for (let i = 0; i < n; i++) {
      const i1 = (i + 1) % n;
      const o = (j * n + i) * 4;
      out[o] = map.data[j * n + i];
      out[o + 1] = map.data[j * n + i1];
      out[o + 2] = map.data[j1 * n + i];
      out[o + 3] = map.data[j1 * n + i1];
    }
  }
  return out;
}

export function heightmapTexture(map: Heightmap): DataTexture {
  return floatTexture(gatheredHeightmap(map), map.size, map.size, RGBAFormat, RepeatWrapping);
}

export function fresnelTexture(table: Float32Array): DataTexture {
  return floatTexture(table, table.length, 1, RedFormat, ClampToEdgeWrapping);
}
