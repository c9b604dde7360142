import { integerNoise } from './integerHash';

/**
 * Perlin noise as the seed report builds it ("Ruido"): an integer noise function,
 * smoothed with its neighbours, interpolated smoothly between lattice points, and summed
 * over octaves of doubling frequency whose amplitudes fall by a persistence factor.
 *
 * Every lattice wraps at its own period, so the result tiles: noise(u + 1, v) equals
 * noise(u, v). That is what lets the heightmaps repeat over the ocean without a seam.
 */
export interface NoiseSettings {
  seed: number;
  /** Lattice cells across one tile in the first octave. */
  baseCells: number;
  octaves: number;
  /** Amplitude ratio between one octave and the next (0..1). */
  persistence: number;
}

export const defaultNoiseSettings: Omit<NoiseSettings, 'seed'> = {
  baseCells: 4,
  octaves: 5,
  persistence: 0.62,
};

/** The seed of octave `octave`'s lattice: each octave gets its own stream so octaves do not repeat one another. */
export function octaveSeed(seed: number, octave: number): number {
  return seed * 7 + octave * 1013;
}

/** The smoothed lattice of one octave: each value is the weighted mean of a 3×3 neighbourhood. */
export function smoothedLattice(cells: number, seed: number): Float64Array {
  const wrap = (i: number) => ((i % cells) + cells) % cells;
  const raw = (x: number, y: number) => integerNoise(wrap(x), wrap(y), seed);
  const lattice = new Float64Array(cells * cells);
  for (let y = 0; y < cells; y++) {
    for (let x = 0; x < cells; x++) {
      const corners = raw(x - 1, y - 1) + raw(x + 1, y - 1) + raw(x - 1, y + 1) + raw(x + 1, y + 1);
      const sides = raw(x - 1, y) + raw(x + 1, y) + raw(x, y - 1) + raw(x, y + 1);
      lattice[y * cells + x] = corners / 16 + sides / 8 + raw(x, y) / 4;
    }
  }
  return lattice;
}

/** The weight of the far end in cosine interpolation: 0 at t = 0, 1 at t = 1, flat at both. */
function cosineWeight(t: number): number {
  return (1 - Math.cos(t * Math.PI)) * 0.5;
}

/** Cosine interpolation, the seed's smooth curve between two lattice values. */
export function cosineInterpolate(a: number, b: number, t: number): number {
  const f = cosineWeight(t);
  return a * (1 - f) + b * f;
}

function interpolatedLattice(lattice: Float64Array, cells: number, u: number, v: number): number {
  const fx = (u - Math.floor(u)) * cells;
  const fy = (v - Math.floor(v)) * cells;
  const x0 = Math.floor(fx) % cells;
  const y0 = Math.floor(fy) % cells;
  const x1 = (x0 + 1) % cells;
  const y1 = (y0 + 1) % cells;
  const tx = fx - Math.floor(fx);
  const ty = fy - Math.floor(fy);
  const top = cosineInterpolate(lattice[y0 * cells + x0], lattice[y0 * cells + x1], tx);
  const bottom = cosineInterpolate(lattice[y1 * cells + x0], lattice[y1 * cells + x1], tx);
  return cosineInterpolate(top, bottom, ty);
}

/**
 * A tiling Perlin noise field, built once per seed. Values lie in [-1, 1]: each octave
 * is bounded by 1 in magnitude and the sum is divided by the sum of the amplitudes.
 */
export class TilingPerlinNoise {
  private readonly octaveLattices: { cells: number; amplitude: number; lattice: Float64Array }[] = [];
  private readonly amplitudeSum: number;

  constructor(readonly settings: NoiseSettings) {
    let amplitude = 1;
    let sum = 0;
    for (let o = 0; o < settings.octaves; o++) {
      const cells = settings.baseCells << o;
      this.octaveLattices.push({ cells, amplitude, lattice: smoothedLattice(cells, octaveSeed(settings.seed, o)) });
      sum += amplitude;
      amplitude *= settings.persistence;
    }
    this.amplitudeSum = sum;
  }

  /** Noise at tile coordinates (u, v); period 1 in both. */
  sample(u: number, v: number): number {
    let total = 0;
    for (const { cells, amplitude, lattice } of this.octaveLattices) {
      total += amplitude * interpolatedLattice(lattice, cells, u, v);
    }
    return total / this.amplitudeSum;
  }

  /**
   * The noise at every point (i / size, j / size) of one tile, row-major: exactly the
   * values sample() gives there, bit for bit (each octave interpolated on the grid by the
   * same arithmetic, then weighted and summed). On the path to the first frame (two 128²
   * maps at start-up), hence the grid's shared work in interpolatedGrid.
   */
  sampleGrid(size: number): Float64Array {
    const totals = new Float64Array(size * size);
    for (const { cells, amplitude, lattice } of this.octaveLattices) {
      const octave = interpolatedGrid(lattice, cells, size);
      for (let k = 0; k < totals.length; k++) totals[k] += amplitude * octave[k];
    }
    for (let k = 0; k < totals.length; k++) totals[k] /= this.amplitudeSum;
    return totals;
  }
}

/**
 * Step 3 for one octave: its lattice cosine-interpolated at every point (i / size, j / size)
 * of the tile, row-major; what interpolatedLattice gives there. Each grid column's lattice
 * cell and weight depend on the column alone (rows likewise), and the interpolation along
 * a lattice row is shared by every grid row that reads it, so each is computed once.
 */
export function interpolatedGrid(lattice: Float64Array, cells: number, size: number): Float64Array {
  const low = new Int32Array(size);
  const high = new Int32Array(size);
  const weight = new Float64Array(size);
  // Columns and rows share coordinates (k / size), so one table serves both.
  for (let k = 0; k < size; k++) {
    const u = k / size;
    const f = (u - Math.floor(u)) * cells;
    low[k] = Math.floor(f) % cells;
    high[k] = (low[k] + 1) % cells;
    weight[k] = cosineWeight(f - Math.floor(f));
  }
  // alongRows[y * size + i]: lattice row y interpolated to column i.
  const alongRows = new Float64Array(cells * size);
  for (let y = 0; y < cells; y++) {
    for (let i = 0; i < size; i++) {
      const fx = weight[i];
      alongRows[y * size + i] = lattice[y * cells + low[i]] * (1 - fx) + lattice[y * cells + high[i]] * fx;
    }
  }
  const grid = new Float64Array(size * size);
  for (let j = 0; j < size; j++) {
    const top = low[j] * size;
    const bottom = high[j] * size;
    const fy = weight[j];
    for (let i = 0; i < size; i++) grid[j * size + i] = alongRows[top + i] * (1 - fy) + alongRows[bottom + i] * fy;
  }
  return grid;
}

export interface Heightmap {
  size: number;
  /** Row-major, data[j * size + i] is the height at tile coordinates (i / size, j / size). */
  data: Float32Array;
}

/**
 * Samples the noise over one tile, then centres it on zero and scales its peak to exactly
 * 1, so a ripple strength in metres is the ripples' true peak height.
 */
export function generateHeightmap(size: number, settings: NoiseSettings): Heightmap {
  const raw = new TilingPerlinNoise(settings).sampleGrid(size);
  let sum = 0;
  for (const value of raw) sum += value;
  const mean = sum / raw.length;
  let peak = 0;
  for (const value of raw) peak = Math.max(peak, Math.abs(value - mean));
  const data = new Float32Array(raw.length);
  for (let k = 0; k < raw.length; k++) data[k] = peak > 0 ? (raw[k] - mean) / peak : 0;
  return { size, data };
}

/** The two ripple heightmaps the ocean blends between, both derived from one seed. */
export function generateRippleHeightmaps(seed: number, size: number): [Heightmap, Heightmap] {
  return [
    generateHeightmap(size, { ...defaultNoiseSettings, seed: seed * 2 }),
    generateHeightmap(size, { ...defaultNoiseSettings, seed: seed * 2 + 1 }),
  ];
}
