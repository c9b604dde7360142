import type { OceanParams } from './params';
import { FftWaveModel } from './fftWaveModel';
import { GerstnerLiveModel } from './gerstnerLiveModel';
import { SeedWaveModel } from './seedWaveModel';
import type { LiveWaveModel, WavesChoice } from './liveWaveModel';

export type { LiveWaveModel, WavesChoice } from './liveWaveModel';

/**
 * How each model is made. Adding a model: add its name to `waves`'s options in params.ts,
 * then the compiler asks for an entry here and one in src/render/waveModels/registry.ts.
 */
const FACTORIES: { [K in WavesChoice]: (params: OceanParams) => LiveWaveModel } = {
  seed: (params) => new SeedWaveModel(params),
  fft: (params) => new FftWaveModel(params),
  gerstner: (params) => new GerstnerLiveModel(params),
};

export function createWaveModel(params: OceanParams): LiveWaveModel {
  return FACTORIES[params.waves](params);
}
