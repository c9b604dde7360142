import { integerNoise } from './integerHash';
import { defaultNoiseSettings, generateRippleHeightmaps, interpolatedGrid, octaveSeed, smoothedLattice } from './perlinNoise';

/**
 * The seed report's Perlin noise taken apart, step by step, for the teaching views: each
 * stage is an array computed by the very functions that make the ripple heightmaps, so the
 * pictures show what the sea is made of, not an illustration of it.
 *
 * Steps 1–3 are shown on one octave's lattice: the first heightmap's third octave, 16 × 16
 * cells, coarse enough that each lattice value is a visible square and fine enough to look
 * like noise (the first octave has only 4 × 4).
 */
export const TEACHING_OCTAVE = 2;

/** One stage's picture: values in [-1, 1], row-major, `size` × `size`. */
export interface StageImage {
  size: number;
  data: Float32Array;
}

export interface NoiseStages {
  /** Step 1: the integer noise alone, one value per lattice point. */
  hash: StageImage;
  /** Step 2: the same lattice, each point the weighted mean of its 3 × 3 neighbourhood. */
  smoothed: StageImage;
  /** Step 3: that lattice cosine-interpolated over the tile (one octave). */
  interpolated: StageImage;
  /** Step 4: every octave summed, centred and scaled to peak 1: the first heightmap as uploaded. */
  octaves: StageImage;
  /** The second heightmap, which the first is blended with in time. */
  second: StageImage;
}

/** The integer noise at every point of a `cells` × `cells` lattice, row-major. */
export function integerLattice(cells: number, seed: number): Float64Array {
  const lattice = new Float64Array(cells * cells);
  for (let y = 0; y < cells; y++) for (let x = 0; x < cells; x++) lattice[y * cells + x] = integerNoise(x, y, seed);
  return lattice;
}

const image = (size: number, values: ArrayLike<number>): StageImage => ({ size, data: Float32Array.from(values) });

/**
 * The stages of the ripple heightmaps for the sea's `seed` (the parameter), heightmaps of
 * `size` × `size`. The first heightmap's noise seed is seed × 2 (generateRippleHeightmaps).
 */
export function noiseStages(seed: number, size: number): NoiseStages {
  const cells = defaultNoiseSettings.baseCells << TEACHING_OCTAVE;
  const latticeSeed = octaveSeed(seed * 2, TEACHING_OCTAVE);
  const smoothed = smoothedLattice(cells, latticeSeed);
  const [first, second] = generateRippleHeightmaps(seed, size);
  return {
    hash: image(cells, integerLattice(cells, latticeSeed)),
    smoothed: image(cells, smoothed),
    interpolated: image(size, interpolatedGrid(smoothed, cells, size)),
    octaves: image(size, first.data),
    second: image(size, second.data),
  };
}

/**
 * The two heightmaps mixed with weight `weight` (seedSurface's rippleBlend; 0 the first, 1 the
 * second): the CPU twin of the blend picture (shaders/panelFigure.frag's mix), which the
 * teaching-view tests hold that picture to.
 */
export function blendedStage(first: StageImage, second: StageImage, weight: number): StageImage {
  const data = new Float32Array(first.data.length);
  for (let k = 0; k < data.length; k++) data[k] = first.data[k] * (1 - weight) + second.data[k] * weight;
  return { size: first.size, data };
}
