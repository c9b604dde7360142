import type { LiveWaveModel, WavesChoice } from '../../sim/waveModels';
import { FftWaveModel } from '../../sim/fftWaveModel';
import { SeedWaveModel } from '../../sim/seedWaveModel';
import { FftWaveView } from './fftWaveView';
import type { WaveModelView } from './waveModelView';
import { SeedWaveView } from './seedWaveView';
import { GerstnerLiveModel } from '../../sim/gerstnerLiveModel';
import { GerstnerWaveView } from './gerstnerWaveView';
import type { WebGLRenderer } from 'three';

/**
 * The render side of each model, keyed like src/sim/waveModels.ts: adding a model to the
 * `waves` parameter makes the compiler ask for an entry here. A view gets the renderer for
 * models that run GPU passes of their own (an FFT); the seed's needs none.
 */
const VIEWS: { [K in WavesChoice]: (model: LiveWaveModel, renderer: WebGLRenderer) => WaveModelView } = {
  seed: (model) => {
    if (!(model instanceof SeedWaveModel)) throw new TypeError(`The seed wave view needs a SeedWaveModel, got '${model.name}'.`);
    return new SeedWaveView(model);
  },
  fft: (model, renderer) => {
    if (!(model instanceof FftWaveModel)) throw new TypeError(`The FFT wave view needs an FftWaveModel, got '${model.name}'.`);
    return new FftWaveView(model, renderer);
  },
  gerstner: (model) => {
    if (!(model instanceof GerstnerLiveModel)) throw new TypeError(`The Gerstner wave view needs a GerstnerLiveModel, got '${model.name}'.`);
    return new GerstnerWaveView(model);
  },
};

export function createWaveModelView(model: LiveWaveModel, renderer: WebGLRenderer): WaveModelView {
  return VIEWS[model.name](model, renderer);
}
