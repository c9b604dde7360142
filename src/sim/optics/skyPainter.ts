import { TilingPerlinNoise } from '../noise/perlinNoise';
import { SUN_DISC_COS_CORE, SUN_DISC_COS_EDGE } from './sunDisc';

/**
 * A procedural sky, painted once into the six faces of a cube map: a gradient from a
 * pale horizon to a deep zenith, a sun disc with its glow, and soft clouds drawn from the
 * same Perlin noise as the waves, projected onto a flat cloud layer.
 */
export type Vec3 = [number, number, number];
export type Rgb = [number, number, number];

/** The cube faces in three.js's loader order, each with its GL face direction for (s, t) in [-1, 1]. */
export const CUBE_FACES = ['px', 'nx', 'py', 'ny', 'pz', 'nz'] as const;
export type CubeFace = (typeof CUBE_FACES)[number];

const faceDirection: Record<CubeFace, (s: number, t: number) => Vec3> = {
  px: (s, t) => [1, -t, -s],
  nx: (s, t) => [-1, -t, s],
  py: (s, t) => [s, 1, t],
  ny: (s, t) => [s, -1, -t],
  pz: (s, t) => [s, -t, 1],
  nz: (s, t) => [-s, -t, -1],
};

/**
 * World direction seen through texel (s, t) of a face. three.js mirrors CubeTexture
 * lookups in x, so the GL direction's x is negated to get the world direction.
 */
export function worldDirectionOfTexel(face: CubeFace, s: number, t: number): Vec3 {
  const [x, y, z] = faceDirection[face](s, t);
  const length = Math.hypot(x, y, z);
  return [-x / length, y / length, z / length];
}

export const ZENITH: Rgb = [0.16, 0.36, 0.68];
export const HORIZON: Rgb = [0.74, 0.83, 0.9];
export const BELOW_HORIZON: Rgb = [0.2, 0.3, 0.36];
export const SUN: Rgb = [1.0, 0.96, 0.86];
export const CLOUD_LIT: Rgb = [1.0, 0.98, 0.95];
export const CLOUD_SHADE: Rgb = [0.66, 0.7, 0.76];
// The GPU painter's dusk (shaders/skyDome.frag), which the shipped PNG faces never had:
// a warm horizon and greyer zenith as the sun nears the horizon, a deep blue once it is
// about 10° below.
export const DUSK_HORIZON: Rgb = [0.96, 0.62, 0.38];
export const DUSK_ZENITH: Rgb = [0.2, 0.3, 0.5];
export const NIGHT_HORIZON: Rgb = [0.16, 0.2, 0.3];
export const NIGHT_ZENITH: Rgb = [0.03, 0.05, 0.12];

/** The cloud layer's Perlin noise: the CPU painter and the GPU painter's baked tile share it. */
export function cloudNoise(cloudSeed = 7): TilingPerlinNoise {
  return new TilingPerlinNoise({ seed: cloudSeed, baseCells: 3, octaves: 6, persistence: 0.55 });
}

/** One tile of cloud density at (i / size, j / size), row-major in v: what sample() gives there. */
export function cloudDensityTile(size: number, cloudSeed = 7): Float64Array {
  return cloudNoise(cloudSeed).sampleGrid(size);
}

const mix = (a: Rgb, b: Rgb, t: number): Rgb => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t];
const smoothstep = (e0: number, e1: number, x: number) => {
  const t = Math.min(1, Math.max(0, (x - e0) / (e1 - e0)));
  return t * t * (3 - 2 * t);
};

export class SkyPainter {
  private readonly clouds: TilingPerlinNoise;

  constructor(
    private readonly sun: Vec3,
    cloudSeed = 7,
  ) {
    this.clouds = cloudNoise(cloudSeed);
  }

  /** sRGB colour in [0, 1] of the sky seen in world direction d (unit length). */
  color(d: Vec3): Rgb {
    const up = d[1];
    let color: Rgb;
    if (up >= 0) {
      color = mix(HORIZON, ZENITH, Math.pow(up, 0.55));
    } else {
      color = mix(HORIZON, BELOW_HORIZON, smoothstep(0, 0.12, -up));
    }

    const cosSun = d[0] * this.sun[0] + d[1] * this.sun[1] + d[2] * this.sun[2];
    const glow = Math.pow(Math.max(cosSun, 0), 8) * 0.35 + Math.pow(Math.max(cosSun, 0), 200) * 0.6;
    color = mix(color, SUN, Math.min(1, glow));

    if (up > 0.01) {
      // Flat cloud layer: (x, z) / y projects the direction onto a plane above the viewer.
      const u = (d[0] / up) * 0.08 + 0.31;
      const v = (d[2] / up) * 0.08 + 0.17;
      const density = this.clouds.sample(u, v);
      const cover = smoothstep(0.02, 0.32, density) * smoothstep(0.01, 0.12, up);
      const lit = mix(CLOUD_SHADE, CLOUD_LIT, 0.5 + 0.5 * Math.max(cosSun, 0));
      color = mix(color, lit, cover * 0.85);
    }

    const sunDisc = smoothstep(SUN_DISC_COS_EDGE, SUN_DISC_COS_CORE, cosSun);
    return mix(color, [1, 1, 1], sunDisc);
  }

  /** One face as RGBA bytes, row 0 at the top. */
  paintFace(face: CubeFace, size: number): Uint8Array {
    const pixels = new Uint8Array(size * size * 4);
    for (let row = 0; row < size; row++) {
      for (let col = 0; col < size; col++) {
        const s = ((col + 0.5) / size) * 2 - 1;
        const t = ((row + 0.5) / size) * 2 - 1;
        const rgb = this.color(worldDirectionOfTexel(face, s, t));
        const o = (row * size + col) * 4;
        pixels[o] = Math.round(Math.min(1, Math.max(0, rgb[0])) * 255);
        pixels[o + 1] = Math.round(Math.min(1, Math.max(0, rgb[1])) * 255);
        pixels[o + 2] = Math.round(Math.min(1, Math.max(0, rgb[2])) * 255);
        pixels[o + 3] = 255;
      }
    }
    return pixels;
  }
}
