import { describe, expect, it } from 'vitest';
import { integerNoise } from '../../../../src/sim/noise/integerHash';
import {
  cosineInterpolate,
  defaultNoiseSettings,
  generateRippleHeightmaps,
  interpolatedGrid,
  octaveSeed,
  smoothedLattice,
  TilingPerlinNoise,
} from '../../../../src/sim/noise/perlinNoise';
import { blendedStage, noiseStages, TEACHING_OCTAVE, type StageImage } from '../../../../src/sim/noise/noiseStages';

const SEED = 4;
const SIZE = 64;
const stages = noiseStages(SEED, SIZE);
const cells = 16;
// The first heightmap's noise seed is seed × 2; its third octave's lattice stream follows from it.
const latticeSeed = SEED * 2 * 7 + TEACHING_OCTAVE * 1013;

/** Root-mean-square difference of two pictures of equal size. */
const rmsDifference = (a: StageImage, b: StageImage) =>
  Math.sqrt(a.data.reduce((sum, v, k) => sum + (v - b.data[k]) ** 2, 0) / a.data.length);
/** A lattice picture spread to `size` × `size`, each lattice value a square, as the view draws it (nearest texel). */
const spread = (lattice: StageImage, size: number): StageImage => ({
  size,
  data: Float32Array.from(
    { length: size * size },
    (_, k) =>
      lattice.data[
        Math.floor((Math.floor(k / size) * lattice.size) / size) * lattice.size + Math.floor(((k % size) * lattice.size) / size)
      ],
  ),
});

describe('the Perlin noise, step by step', () => {
  it('step 1 is the integer noise at each lattice point of the first heightmap’s third octave, 16 × 16', () => {
    expect(octaveSeed(SEED * 2, TEACHING_OCTAVE)).toBe(latticeSeed);
    expect(stages.hash.size).toBe(cells);
    expect(defaultNoiseSettings.baseCells << TEACHING_OCTAVE).toBe(cells);
    for (let y = 0; y < cells; y++)
      for (let x = 0; x < cells; x++) expect(stages.hash.data[y * cells + x]).toBe(Math.fround(integerNoise(x, y, latticeSeed)));
  });

  // Control: another octave’s lattice.
  it('step 2 is the seed report’s 3 × 3 smoothing of step 1, wrapping at the lattice’s edge', () => {
    const raw = (x: number, y: number) => stages.hash.data[((y + cells) % cells) * cells + ((x + cells) % cells)];
    let worst = 0;
    for (let y = 0; y < cells; y++) {
      for (let x = 0; x < cells; x++) {
        const corners = raw(x - 1, y - 1) + raw(x + 1, y - 1) + raw(x - 1, y + 1) + raw(x + 1, y + 1);
        const sides = raw(x - 1, y) + raw(x + 1, y) + raw(x, y - 1) + raw(x, y + 1);
        worst = Math.max(worst, Math.abs(stages.smoothed.data[y * cells + x] - (corners / 16 + sides / 8 + raw(x, y) / 4)));
      }
    }
    // Float32 storage of each value: about 1e-7.
    expect(worst).toBeLessThan(1e-6);
    const otherOctave = new Float32Array(cells * cells).map((_, k) =>
      integerNoise(k % cells, Math.floor(k / cells), octaveSeed(SEED * 2, 0)),
    );
    expect(rmsDifference(stages.hash, { size: cells, data: otherOctave })).toBeGreaterThan(0.3);
  });

  it('step 3 passes through the smoothed lattice and follows the cosine curve between its points', () => {
    const per = SIZE / cells;
    const lattice = (x: number, y: number) => stages.smoothed.data[(y % cells) * cells + (x % cells)];
    for (let y = 0; y < cells; y++) {
      for (let x = 0; x < cells; x++) {
        expect(stages.interpolated.data[y * per * SIZE + x * per]).toBeCloseTo(lattice(x, y), 6);
        // A quarter of the way along a lattice row: the cosine weight, not the straight line's.
        const quarter = stages.interpolated.data[y * per * SIZE + x * per + per / 4];
        expect(quarter).toBeCloseTo(cosineInterpolate(lattice(x, y), lattice(x + 1, y), 0.25), 6);
      }
    }
  });

  it('step 4 is the first heightmap exactly as the sea receives it; the second is the map it blends with', () => {
    const [first, second] = generateRippleHeightmaps(SEED, SIZE);
    expect(stages.octaves.data).toEqual(first.data);
    expect(stages.second.data).toEqual(second.data);
    // Step 3 is one of the octaves step 4 sums: Σ pᵒ·octaveₒ / Σ pᵒ is the map's noise, bit for bit.
    const { octaves, persistence, baseCells } = defaultNoiseSettings;
    const sum = new Float64Array(SIZE * SIZE);
    let amplitude = 1;
    let amplitudes = 0;
    for (let o = 0; o < octaves; o++) {
      const grid = interpolatedGrid(smoothedLattice(baseCells << o, octaveSeed(SEED * 2, o)), baseCells << o, SIZE);
      if (o === TEACHING_OCTAVE) expect(Float32Array.from(grid).every((v, k) => v === stages.interpolated.data[k])).toBe(true);
      for (let k = 0; k < sum.length; k++) sum[k] += amplitude * grid[k];
      amplitudes += amplitude;
      amplitude *= persistence;
    }
    const noise = new TilingPerlinNoise({ ...defaultNoiseSettings, seed: SEED * 2 }).sampleGrid(SIZE);
    expect(sum.every((v, k) => v / amplitudes === noise[k])).toBe(true);
  });

  it('each stage’s picture differs from the next, the blend lying between the two heightmaps', () => {
    const order = [
      spread(stages.hash, SIZE),
      spread(stages.smoothed, SIZE),
      stages.interpolated,
      stages.octaves,
      blendedStage(stages.octaves, stages.second, 0.5),
    ];
    for (let i = 0; i + 1 < order.length; i++)
      expect(rmsDifference(order[i], order[i + 1]), `stage ${i} to ${i + 1}`).toBeGreaterThan(0.05);
    // Control for the check itself: a stage against itself.
    expect(rmsDifference(stages.octaves, stages.octaves)).toBe(0);
    const half = blendedStage(stages.octaves, stages.second, 0.5);
    expect(blendedStage(stages.octaves, stages.second, 0).data).toEqual(stages.octaves.data);
    expect(blendedStage(stages.octaves, stages.second, 1).data).toEqual(stages.second.data);
    for (let k = 0; k < half.data.length; k += 97)
      expect(half.data[k]).toBeCloseTo((stages.octaves.data[k] + stages.second.data[k]) / 2, 6);
  });

  it('smoothing keeps the range but lowers the contrast: the spread of step 2 is well under step 1’s', () => {
    const std = (image: StageImage) => {
      const mean = image.data.reduce((a, b) => a + b, 0) / image.data.length;
      return Math.sqrt(image.data.reduce((a, b) => a + (b - mean) ** 2, 0) / image.data.length);
    };
    // Uniform noise on [−1, 1) has σ = 1/√3 ≈ 0.58; the 1/4, 1/8, 1/16 weights leave √(0.1406) of it, ≈ 0.22.
    expect(std(stages.hash)).toBeGreaterThan(0.45);
    expect(std(stages.smoothed)).toBeLessThan(0.32);
  });
});
