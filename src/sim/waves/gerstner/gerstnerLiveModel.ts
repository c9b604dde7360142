import { angularFrequency } from '../dispersion';
import { spreadingFunction } from '../spectra/directionalSpreading';
import { gerstnerSea } from './gerstnerSpectrum';
import { gerstnerSlopeVariance } from './gerstnerSlopes';
import { GerstnerWaveModel, type GerstnerWave } from './gerstnerWaves';
import type { OceanParams } from '../../params/params';
import { seaStateFromParams, windVector } from '../spectra/seaState';
import { frequencySpectrum } from '../spectra/waveSpectrum';
import type { DisplacementBounds, SurfaceSample } from '../waveModel';
import type { LiveWaveModel } from '../waveModel';

/** The parameters the Gerstner sea is drawn from: the FFT sea's wind and spectrum, plus count and Q. */
export type GerstnerSeaParams = Pick<
  OceanParams,
  | 'seed'
  | 'gerstnerCount'
  | 'gerstnerSteepness'
  | 'windSpeed'
  | 'windDirection'
  | 'spectrum'
  | 'fetch'
  | 'depth'
  | 'spreading'
  | 'spreadingModel'
>;

const SEA_KEYS: readonly (keyof GerstnerSeaParams)[] = [
  'seed',
  'gerstnerCount',
  'gerstnerSteepness',
  'windSpeed',
  'windDirection',
  'spectrum',
  'fetch',
  'depth',
  'spreading',
  'spreadingModel',
];

/**
 * The waves params describe: N trochoids drawn (gerstnerSea) from the same frequency
 * spectrum (PM, JONSWAP or Phillips, src/sim/waves/spectra/waveSpectrum.ts), cos-2s spreading about the
 * same wind and the same dispersion ω² = g k tanh(k h) as the FFT sea, with the same seed.
 */
export function gerstnerWavesFor(params: GerstnerSeaParams): GerstnerWave[] {
  const sea = seaStateFromParams({ ...params, choppiness: 1, fftSize: '128' });
  const spectrum = frequencySpectrum(sea);
  const [wx, wz] = windVector(sea.windDirection);
  return gerstnerSea({
    count: params.gerstnerCount,
    seed: params.seed,
    spectrum: spectrum.density,
    spreading: spreadingFunction(sea.spreadingModel, sea.spreading, spectrum.peak, sea.windSpeed),
    windDirection: Math.atan2(wz, wx),
    steepness: params.gerstnerSteepness,
    dispersion: (k) => angularFrequency(k, sea.depth),
  });
}

/**
 * The Gerstner sea as the app runs it (waves=gerstner): a GerstnerWaveModel remade whenever
 * a parameter it is drawn from changes. sample() and height() invert the horizontal motion
 * (Newton, see invertGerstner), so the boat and the underwater switch read the surface
 * above the world point, not above the grid point.
 */
export class GerstnerLiveModel implements LiveWaveModel {
  readonly name = 'gerstner';
  private key = '';
  private twin: GerstnerWaveModel;
  /** See LiveWaveModel: the wave table is remade exactly when the surface changes. */
  surfaceRevision = 0;

  constructor(params: GerstnerSeaParams) {
    this.twin = new GerstnerWaveModel([]);
    this.setParams(params);
  }

  /** The model of the current waves (its wave table is what the GPU draws). */
  get model(): GerstnerWaveModel {
    return this.twin;
  }

  get waves(): readonly GerstnerWave[] {
    return this.twin.waves;
  }

  /** Returns true when the wave table changed and must be uploaded again. */
  setParams(params: GerstnerSeaParams): boolean {
    const key = SEA_KEYS.map((k) => String(params[k])).join('|');
    if (key === this.key) return false;
    this.key = key;
    this.surfaceRevision++;
    this.twin = new GerstnerWaveModel(gerstnerWavesFor(params));
    return true;
  }

  displacement(x: number, z: number, time: number): [number, number, number] {
    return this.twin.displacement(x, z, time);
  }

  sample(x: number, z: number, time: number): SurfaceSample {
    return this.twin.sample(x, z, time);
  }

  height(x: number, z: number, time: number): number {
    return this.twin.sample(x, z, time).height;
  }

  /** See LiveWaveModel: the trochoids' mean-square slopes summed (constant in time). */
  slopeVariance(): number {
    return gerstnerSlopeVariance(this.twin.waves);
  }

  bounds(): DisplacementBounds {
    return this.twin.bounds();
  }
}
