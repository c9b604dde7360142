import { describe, expect, it } from 'vitest';
import { integerNoise, seededRandom } from '../../../../src/sim/noise/integerHash';
import {
  TilingPerlinNoise,
  cosineInterpolate,
  generateHeightmap,
  generateRippleHeightmaps,
  defaultNoiseSettings,
} from '../../../../src/sim/noise/perlinNoise';

describe('integer noise', () => {
  it('is the MurmurHash3 finaliser of the mixed lattice point and seed, as documented', () => {
    // Written out separately in Python from the constants in integerHash.ts's comment and code
    // (32-bit wrap-around products, h ^= h >> 16, × 0x85ebca6b, h ^= h >> 13, × 0xc2b2ae35,
    // h ^= h >> 16, then h / 2³¹ − 1), not by calling this module.
    const expected: [number, number, number, number][] = [
      [0, 0, 0, -1],
      [1, 0, 0, -0.8603595807217062],
      [0, 1, 0, 0.476229693274945],
      [3, -7, 9, 0.09635292738676071],
      [-50, -150, 9, 0.8836115980520844],
      [123456, 654321, 42, 0.45925501035526395],
      [5, 5, 2147483647, -0.25943325366824865],
    ];
    for (const [x, y, seed, value] of expected) expect(integerNoise(x, y, seed), `(${x}, ${y}, ${seed})`).toBe(value);
  });
  it('is bounded in [-1, 1) and roughly zero-mean', () => {
    let sum = 0;
    for (let y = 0; y < 100; y++) {
      for (let x = 0; x < 100; x++) {
        const v = integerNoise(x, y, 3);
        expect(v).toBeGreaterThanOrEqual(-1);
        expect(v).toBeLessThan(1);
        sum += v;
      }
    }
    expect(Math.abs(sum / 10000)).toBeLessThan(0.03);
  });
  it('changes with the seed', () => {
    let same = 0;
    for (let x = 0; x < 200; x++) if (integerNoise(x, 1, 1) === integerNoise(x, 1, 2)) same++;
    expect(same).toBe(0);
  });
});

describe('cosine interpolation', () => {
  it('hits both ends and the midpoint, with zero slope at the ends', () => {
    expect(cosineInterpolate(2, 6, 0)).toBeCloseTo(2, 12);
    expect(cosineInterpolate(2, 6, 1)).toBeCloseTo(6, 12);
    expect(cosineInterpolate(2, 6, 0.5)).toBeCloseTo(4, 12);
    expect(cosineInterpolate(2, 6, 1e-4) - 2).toBeLessThan(1e-6);
  });
});

describe('tiling Perlin noise', () => {
  const settings = { ...defaultNoiseSettings, seed: 42 };
  const noise = new TilingPerlinNoise(settings);

  it('is the smoothed integer noise at lattice points, and their plain mean halfway between', () => {
    // One octave of 8 cells on seed 42, whose lattice stream is seed × 7 (perlinNoise.ts).
    const cells = 8;
    const field = new TilingPerlinNoise({ seed: 42, baseCells: cells, octaves: 1, persistence: 0.5 });
    const raw = (x: number, y: number) => integerNoise(((x % cells) + cells) % cells, ((y % cells) + cells) % cells, 42 * 7);
    // The seed report's smoothing: corners 1/16, sides 1/8, centre 1/4.
    const smooth = (x: number, y: number) =>
      (raw(x - 1, y - 1) + raw(x + 1, y - 1) + raw(x - 1, y + 1) + raw(x + 1, y + 1)) / 16 +
      (raw(x - 1, y) + raw(x + 1, y) + raw(x, y - 1) + raw(x, y + 1)) / 8 +
      raw(x, y) / 4;
    for (let y = 0; y < cells; y++) {
      for (let x = 0; x < cells; x++) {
        expect(field.sample(x / cells, y / cells)).toBeCloseTo(smooth(x, y), 12);
        // Cosine interpolation weighs both ends by 1/2 at the middle of a cell edge.
        expect(field.sample((x + 0.5) / cells, y / cells)).toBeCloseTo((smooth(x, y) + smooth(x + 1, y)) / 2, 12);
      }
    }
  });

  it('gives another field for another seed', () => {
    const other = new TilingPerlinNoise({ ...settings, seed: 43 });
    let same = 0;
    for (let k = 0; k < 200; k++) if (other.sample(k * 0.013, k * 0.029) === noise.sample(k * 0.013, k * 0.029)) same++;
    expect(same).toBe(0);
  });

  it('is bounded by 1 in magnitude', () => {
    for (let k = 0; k < 5000; k++) expect(Math.abs(noise.sample(k * 0.0071, k * 0.0113))).toBeLessThanOrEqual(1);
  });

  it('tiles with period 1 in both directions', () => {
    for (let k = 0; k < 200; k++) {
      const u = k * 0.0173;
      const v = k * 0.0311;
      expect(noise.sample(u + 1, v)).toBeCloseTo(noise.sample(u, v), 10);
      expect(noise.sample(u, v + 1)).toBeCloseTo(noise.sample(u, v), 10);
      expect(noise.sample(u - 3, v + 2)).toBeCloseTo(noise.sample(u, v), 10);
    }
  });

  it('is continuous: tiny steps give tiny changes, including across the tile edge', () => {
    const h = 1e-6;
    for (let k = 0; k < 500; k++) {
      const u = k / 500;
      expect(Math.abs(noise.sample(u + h, 0.37) - noise.sample(u, 0.37))).toBeLessThan(1e-3);
    }
    expect(Math.abs(noise.sample(1 - h, 0.5) - noise.sample(0, 0.5))).toBeLessThan(1e-3);
  });

  it('gains detail with octaves: more octaves add high-frequency energy', () => {
    // Total variation along a line relative to the spread of values: larger when finer octaves are present.
    const roughness = (octaves: number) => {
      const field = new TilingPerlinNoise({ ...settings, octaves });
      const values = Array.from({ length: 2001 }, (_, k) => field.sample(k / 2000, 0.3));
      let variation = 0;
      for (let k = 1; k < values.length; k++) variation += Math.abs(values[k] - values[k - 1]);
      const mean = values.reduce((a, b) => a + b, 0) / values.length;
      const std = Math.sqrt(values.reduce((a, b) => a + (b - mean) ** 2, 0) / values.length);
      return variation / std;
    };
    expect(roughness(5)).toBeGreaterThan(roughness(1) * 1.5);
  });
});

describe('heightmaps', () => {
  it('are zero-mean with peak exactly 1, and tile without a seam', () => {
    const map = generateHeightmap(64, { ...defaultNoiseSettings, seed: 5 });
    let peak = 0;
    let sum = 0;
    for (const v of map.data) {
      peak = Math.max(peak, Math.abs(v));
      sum += v;
    }
    expect(peak).toBeCloseTo(1, 6);
    expect(Math.abs(sum / map.data.length)).toBeLessThan(1e-6);
    // The seam: the step from the last column to the first is no bigger than ordinary steps.
    let worstInside = 0;
    let worstSeam = 0;
    for (let j = 0; j < 64; j++) {
      for (let i = 0; i < 63; i++) worstInside = Math.max(worstInside, Math.abs(map.data[j * 64 + i + 1] - map.data[j * 64 + i]));
      worstSeam = Math.max(worstSeam, Math.abs(map.data[j * 64] - map.data[j * 64 + 63]));
    }
    expect(worstSeam).toBeLessThanOrEqual(worstInside * 1.05);
  });

  it('are the same for the same seed and different for another', () => {
    const [a0, a1] = generateRippleHeightmaps(7, 32);
    const [b0] = generateRippleHeightmaps(7, 32);
    const [c0] = generateRippleHeightmaps(8, 32);
    expect(Array.from(a0.data)).toEqual(Array.from(b0.data));
    expect(Array.from(a0.data)).not.toEqual(Array.from(a1.data));
    expect(Array.from(a0.data)).not.toEqual(Array.from(c0.data));
  });
});

describe('grid sampling (the start-up fast path)', () => {
  // Fast path against brute force: sampleGrid must equal sample() bit for bit, since the
  // heightmaps (and so every reference picture) are built from it.
  for (const caseSeed of [11, 29, 4243]) {
    it(`equals sample() exactly at every grid point, seeded case ${caseSeed}`, () => {
      const random = seededRandom(caseSeed);
      for (let trial = 0; trial < 4; trial++) {
        const settings = {
          seed: Math.floor(random() * 2147483647),
          baseCells: 1 + Math.floor(random() * 6),
          octaves: 1 + Math.floor(random() * 6),
          persistence: 0.3 + random() * 0.6,
        };
        const size = [8, 24, 64, 100][trial];
        const noise = new TilingPerlinNoise(settings);
        const grid = noise.sampleGrid(size);
        for (let j = 0; j < size; j++) {
          for (let i = 0; i < size; i++) {
            if (!Object.is(grid[j * size + i], noise.sample(i / size, j / size))) {
              throw new Error(
                `grid (${i}, ${j}) of size ${size} with ${JSON.stringify(settings)}: ${grid[j * size + i]} ≠ ${noise.sample(i / size, j / size)}`,
              );
            }
          }
        }
      }
    });
  }

  it('keeps the default ripple heightmaps of seed 1 exactly as they were first published', () => {
    // Values of the original per-sample implementation; a change here changes every picture.
    const [first, second] = generateRippleHeightmaps(1, 128);
    expect(first.data[0]).toBe(-0.4126792848110199);
    expect(first.data[1]).toBe(-0.5061705112457275);
    expect(first.data[127]).toBe(-0.4128729999065399);
    expect(first.data[128 * 64 + 64]).toBe(0.4785279929637909);
    expect(first.data[16383]).toBe(-0.4435376524925232);
    expect(second.data[0]).toBe(-0.43933647871017456);
    expect(second.data[5000]).toBe(-0.24635933339595795);
  });
});
