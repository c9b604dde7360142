import { timeInPeriod } from '../dispersion';
import { initialSpectrum, REPEAT_PERIOD, type SpectralTile } from '../spectra/initialSpectrum';
import type { SeaState } from '../spectra/seaState';
import { directionalSpectrum, frequencySpectrum, peakWavelength } from '../spectra/waveSpectrum';
import { cascadeLayout } from './cascades';
import { evolveSpectra } from './spectralFields';
import { stockhamRadices, stockhamRadixStage } from './stockhamFft';

/** One mixed-radix Stockham stage (stockhamRadixStage's signature), so a test can plant a faulty one. */
export type RadixStage = (input: Float64Array, n: number, halfSize: number, radix: number) => Float64Array;

/** A row of the sea traced through the FFT: the row's spectrum, then the array after each stage. */
export interface RowStages {
  n: number;
  /** Side of the cascade's tile (m). */
  tileSize: number;
  /** The radix of each stage, as the GPU runs them (stockhamRadices). */
  radices: number[];
  /** Interleaved complex arrays: [0] the row's spectrum, [s + 1] after stage s; the last is the row of heights. */
  stages: Float64Array[];
}

/**
 * The row z = 0 of a tile's height field, still in frequency space along x: the 2-D inverse
 * DFT at q = 0 sums each column over kz (e^{2πi b·0/n} = 1), so its x-spectrum is
 * Σ_b h̃(kx_a, kz_b, τ). h̃ is taken from evolveSpectra without choppiness, where spectra[0]
 * is i·h̃ (no horizontal part), so the heights are the very ones the CPU twin computes.
 */
export function rowSpectrumAtZ0(tile: SpectralTile, tau: number): Float64Array {
  const n = tile.n;
  const [packed] = evolveSpectra(tile, tau, 0);
  const row = new Float64Array(2 * n);
  for (let b = 0; b < n; b++) {
    for (let a = 0; a < n; a++) {
      const i = b * n + a;
      // h̃ = −i·(i h̃)
      row[2 * a] += packed[2 * i + 1];
      row[2 * a + 1] -= packed[2 * i];
    }
  }
  return row;
}

/** The row run through the Stockham stages of stockhamRadices(n), every intermediate kept. */
export function rowThroughStages(row: Float64Array, n: number, stage: RadixStage = stockhamRadixStage): Float64Array[] {
  const stages = [row];
  let halfSize = 1;
  for (const radix of stockhamRadices(n)) {
    stages.push(stage(stages[stages.length - 1], n, halfSize, radix));
    halfSize *= radix;
  }
  return stages;
}

let cached: { key: string; tile: SpectralTile } | null = null;

/** Cascade 0's h₀ for this sea, drawn as fftOceanSetup draws it (same seed and stream), kept while the sea stays the same. */
function firstTile(sea: SeaState): SpectralTile {
  const key = JSON.stringify(sea);
  if (cached?.key !== key) {
    const spectrum = frequencySpectrum(sea);
    const [cascade] = cascadeLayout(peakWavelength(sea), sea.fftSize);
    cached = { key, tile: initialSpectrum(cascade, sea.fftSize, directionalSpectrum(sea, spectrum), sea.depth, sea.seed, 0) };
  }
  return cached.tile;
}

/** The live sea's row z = 0 of cascade 0 at `time` (s), through the FFT stage by stage. */
export function liveRowStages(sea: SeaState, time: number, stage: RadixStage = stockhamRadixStage): RowStages {
  const tile = firstTile(sea);
  const n = sea.fftSize;
  const row = rowSpectrumAtZ0(tile, timeInPeriod(time, REPEAT_PERIOD));
  return { n, tileSize: tile.cascade.size, radices: stockhamRadices(n), stages: rowThroughStages(row, n, stage) };
}
