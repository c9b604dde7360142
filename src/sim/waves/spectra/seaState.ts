import { DEEP } from '../dispersion';
import type { SpreadingModel } from './directionalSpreading';

/** Which published frequency spectrum the wind sea follows. */
export type SpectrumName = 'pierson-moskowitz' | 'jonswap' | 'phillips';

/**
 * Everything the spectral (Tessendorf FFT) sea is drawn from, in SI units. The parameter
 * table (params.ts) has the user-facing names and ranges; fetch is in metres here.
 */
export interface SeaState {
  /** U10, wind speed 10 m above the sea, m/s. */
  windSpeed: number;
  /** Direction the wind blows towards, degrees clockwise from −z (as sunAzimuth). */
  windDirection: number;
  spectrum: SpectrumName;
  /** Fetch for JONSWAP, m. */
  fetch: number;
  /** Water depth, m; DEEP (Infinity) for deep water. */
  depth: number;
  /** cos-2s spreading exponent s (larger: narrower around the wind). */
  spreading: number;
  /** cos-2s with s at every frequency, or Hasselmann et al. (1980)'s s(ω) (src/sim/waves/spectra/directionalSpreading.ts). */
  spreadingModel: SpreadingModel;
  /** λ, the scale of the choppy horizontal displacement (0: none, 1: Gerstner-like). */
  choppiness: number;
  /** Grid points per side of every cascade's FFT. */
  fftSize: 64 | 128 | 256;
  /** Seed of the Gaussian draw of h₀(k). */
  seed: number;
}

export const DEFAULT_SEA_STATE: SeaState = {
  windSpeed: 10,
  windDirection: 20,
  spectrum: 'pierson-moskowitz',
  fetch: 100_000,
  depth: DEEP,
  spreading: 8,
  spreadingModel: 'cos-2s',
  choppiness: 1,
  fftSize: 128,
  seed: 1,
};

/** Unit vector (x, z) the wind blows towards. */
export function windVector(windDirectionDeg: number): [number, number] {
  const a = (windDirectionDeg * Math.PI) / 180;
  return [Math.sin(a), -Math.cos(a)];
}

/** The parameters of the spectral sea, as the parameter table (params.ts) holds them. */
export interface SeaParams {
  windSpeed: number;
  windDirection: number;
  spectrum: SpectrumName;
  /** km */
  fetch: number;
  /** m; the table's maximum, 1000, means deep water */
  depth: number;
  spreading: number;
  spreadingModel: SpreadingModel;
  choppiness: number;
  fftSize: '64' | '128' | '256';
  seed: number;
}

/** Depth at and above which the sea is treated as deep (the depth parameter's maximum). */
export const DEEP_PARAM_DEPTH = 1000;

export function seaStateFromParams(p: SeaParams): SeaState {
  return {
    windSpeed: p.windSpeed,
    windDirection: p.windDirection,
    spectrum: p.spectrum,
    fetch: p.fetch * 1000,
    depth: p.depth >= DEEP_PARAM_DEPTH ? DEEP : p.depth,
    spreading: p.spreading,
    spreadingModel: p.spreadingModel,
    choppiness: p.choppiness,
    fftSize: Number(p.fftSize) as SeaState['fftSize'],
    seed: p.seed,
  };
}
