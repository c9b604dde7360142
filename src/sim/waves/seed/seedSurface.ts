import type { Heightmap } from '../../noise/perlinNoise';
import type { OceanParams } from '../../params/params';

/**
 * The displacement function M(x, z) of the seed report, on the CPU. Its GLSL twin is
 * shaders/waves/seed.glsl; both read the same SurfaceState, so every time-dependent
 * phase is computed here once, in double precision, and reduced to [0, 2π) or to one
 * tile before it reaches the GPU. That keeps float32 shaders exact at t = 10⁶ s.
 */
export const GRAVITY = 9.81;
/** World size of one ripple heightmap tile, metres. */
export const RIPPLE_TILE_SIZE = 96;
/** Texels across one ripple heightmap. */
export const HEIGHTMAP_SIZE = 128;
/** Spacing of the fabricated neighbours M(x+Δ, z) and M(x, z+Δ), metres. */
export const NORMAL_DELTA = 1.0;

/** The second swell product is a smaller, shorter wave at another heading: without it the swell is a visible egg crate. */
export const SECOND_SWELL = { amplitude: 0.45, frequency: 1.73, cos: 0.8, sin: 0.6 };
/** Drift of each heightmap across the sea, m/s: the two layers slide past each other while they blend. */
const RIPPLE_DRIFT: [[number, number], [number, number]] = [
  [0.55, 0.2],
  [-0.25, 0.45],
];

const TWO_PI = Math.PI * 2;

export interface SurfaceState {
  swellAmplitude: number;
  swellFrequency: number;
  /** Phases of the two swell products, each [x-phase, z-phase], in [0, 2π). */
  swellPhase: [number, number, number, number];
  rippleStrength: number;
  /** Weight of the second heightmap, 0..1, varying smoothly in time. */
  rippleBlend: number;
  /** Drift offsets of the two heightmaps, metres, in [0, tile). */
  rippleOffset: [number, number, number, number];
  tileSize: number;
  normalDelta: number;
}

function wrapPhase(phase: number): number {
  const wrapped = phase % TWO_PI;
  return wrapped < 0 ? wrapped + TWO_PI : wrapped;
}

function wrapTile(offset: number): number {
  const wrapped = offset % RIPPLE_TILE_SIZE;
  return wrapped < 0 ? wrapped + RIPPLE_TILE_SIZE : wrapped;
}

/** Deep-water dispersion ω = √(g k): the swell moves at the speed real waves of its length do. */
export function deepWaterAngularFrequency(waveNumber: number): number {
  return Math.sqrt(GRAVITY * waveNumber);
}

export function surfaceStateAt(
  params: Pick<OceanParams, 'swellAmplitude' | 'swellFrequency' | 'rippleStrength' | 'rippleBlendSpeed'>,
  time: number,
): SurfaceState {
  const k1 = params.swellFrequency;
  const k2 = k1 * SECOND_SWELL.frequency;
  const w1 = deepWaterAngularFrequency(k1) * time;
  const w2 = deepWaterAngularFrequency(k2) * time;
  return {
    swellAmplitude: params.swellAmplitude,
    swellFrequency: k1,
    swellPhase: [wrapPhase(w1), wrapPhase(0.7 * w1), wrapPhase(w2), wrapPhase(0.6 * w2 + 1.3)],
    rippleStrength: params.rippleStrength,
    rippleBlend: 0.5 - 0.5 * Math.cos(wrapPhase(params.rippleBlendSpeed * time)),
    rippleOffset: [
      wrapTile(RIPPLE_DRIFT[0][0] * time),
      wrapTile(RIPPLE_DRIFT[0][1] * time),
      wrapTile(RIPPLE_DRIFT[1][0] * time),
      wrapTile(RIPPLE_DRIFT[1][1] * time),
    ],
    tileSize: RIPPLE_TILE_SIZE,
    normalDelta: NORMAL_DELTA,
  };
}

/** The largest |height| the surface can reach with these parameters: used to inflate bounds. */
export function maxDisplacement(params: Pick<OceanParams, 'swellAmplitude' | 'rippleStrength'>): number {
  return params.swellAmplitude * (1 + SECOND_SWELL.amplitude) + params.rippleStrength;
}

/** The seed's "movimiento" swell: products of sines and cosines of the coordinate times a frequency, times an amplitude. */
export function swellHeight(state: SurfaceState, x: number, z: number): number {
  const k = state.swellFrequency;
  const [p1x, p1z, p2x, p2z] = state.swellPhase;
  const first = Math.sin(k * x + p1x) * Math.cos(k * z + p1z);
  const k2 = k * SECOND_SWELL.frequency;
  const u = SECOND_SWELL.cos * x + SECOND_SWELL.sin * z;
  const v = -SECOND_SWELL.sin * x + SECOND_SWELL.cos * z;
  const second = Math.sin(k2 * u + p2x) * Math.cos(k2 * v + p2z);
  return state.swellAmplitude * (first + SECOND_SWELL.amplitude * second);
}

/**
 * Bilinear sample with wrap, texel (i, j) sitting at world offset (i, j) · tile / size.
 * The shader does the same arithmetic with texelFetch rather than relying on hardware
 * filtering, whose precision differs between GPUs.
 */
export function sampleHeightmap(map: Heightmap, tileSize: number, x: number, z: number): number {
  const n = map.size;
  const s = ((((x / tileSize) % 1) + 1) % 1) * n;
  const t = ((((z / tileSize) % 1) + 1) % 1) * n;
  const i0 = Math.floor(s);
  const j0 = Math.floor(t);
  const fx = s - i0;
  const fz = t - j0;
  const i = i0 % n;
  const j = j0 % n;
  const i1 = (i + 1) % n;
  const j1 = (j + 1) % n;
  const d = map.data;
  const top = d[j * n + i] * (1 - fx) + d[j * n + i1] * fx;
  const bottom = d[j1 * n + i] * (1 - fx) + d[j1 * n + i1] * fx;
  return top * (1 - fz) + bottom * fz;
}

export function rippleHeight(state: SurfaceState, maps: readonly [Heightmap, Heightmap], x: number, z: number): number {
  const [ox0, oz0, ox1, oz1] = state.rippleOffset;
  const a = sampleHeightmap(maps[0], state.tileSize, x + ox0, z + oz0);
  const b = sampleHeightmap(maps[1], state.tileSize, x + ox1, z + oz1);
  return state.rippleStrength * (a + (b - a) * state.rippleBlend);
}

/** M(x, z): the surface height, swell then ripples, as the seed's MovimientoOceano. */
export function surfaceHeight(state: SurfaceState, maps: readonly [Heightmap, Heightmap], x: number, z: number): number {
  return swellHeight(state, x, z) + rippleHeight(state, maps, x, z);
}

/**
 * The seed's fabricated-neighbour normal: V1 = M(x, z), V2 = M(x+Δ, z), V3 = M(x, z+Δ),
 * and the normal of the triangle they span. With x to the right and z towards the viewer
 * (three.js's right-handed, y-up frame), (V3 − V1) × (V2 − V1) is the upward one.
 */
export function surfaceNormal(state: SurfaceState, maps: readonly [Heightmap, Heightmap], x: number, z: number): [number, number, number] {
  const d = state.normalDelta;
  const h1 = surfaceHeight(state, maps, x, z);
  const h2 = surfaceHeight(state, maps, x + d, z);
  const h3 = surfaceHeight(state, maps, x, z + d);
  // (0, h3 − h1, d) × (d, h2 − h1, 0)
  const nx = -(h2 - h1) * d;
  const ny = d * d;
  const nz = -(h3 - h1) * d;
  const length = Math.hypot(nx, ny, nz);
  return [nx / length, ny / length, nz / length];
}
