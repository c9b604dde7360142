import type { WebGLRenderer } from 'three';
import type { OceanParams } from '../../sim/params/params';
import type { WavesChoice } from '../../sim/waves/waveModel';
import { SeedWaveModel } from '../../sim/waves/seed/seedWaveModel';
import { compareModelNames } from '../../sim/compare/compareLayout';
import type { WaveModelView } from './waveModelView';
import { SeedWaveView } from './seed/seedWaveView';

/** Makes one model's CPU twin and GPU half for these parameters. */
export type WaveModelMaker = (params: OceanParams, renderer: WebGLRenderer) => WaveModelView;

/**
 * How the render side gets each model's code, keyed by the `waves` parameter: adding a
 * model to the `waves` parameter makes the compiler ask for an entry here. The seed's is in
 * the page's own chunk (the default first frame draws it); every other model's code is a
 * chunk of its own, fetched the first time a view needs it, so the page loads less before its
 * first frame. A maker gets the renderer for models that run GPU passes of their
 * own (an FFT).
 */
const LOADERS: { [K in WavesChoice]: () => Promise<WaveModelMaker> } = {
  seed: () => Promise.resolve(makeSeedWaveView),
  fft: () => import('./fft/fftModelCode').then((code) => code.makeFftWaveView),
  gerstner: () => import('./gerstner/gerstnerModelCode').then((code) => code.makeGerstnerWaveView),
};

function makeSeedWaveView(params: OceanParams): WaveModelView {
  return new SeedWaveView(new SeedWaveModel(params));
}

const makers = new Map<WavesChoice, WaveModelMaker>([['seed', makeSeedWaveView]]);
const loads = new Map<WavesChoice, Promise<void>>();

/** Every model these parameters draw: `waves`, or each of a comparison's. */
export function modelsDrawn(params: Pick<OceanParams, 'waves' | 'compare'>): WavesChoice[] {
  const compared = compareModelNames<WavesChoice>(params.compare);
  return compared.length > 0 ? compared : [params.waves];
}

/** Those of `names` whose code has not arrived yet. */
export function modelsMissing(names: readonly WavesChoice[]): WavesChoice[] {
  return names.filter((name) => !makers.has(name));
}

/**
 * Fetches the code of every named model not loaded yet. Rejects when one cannot be fetched
 * (the network, a stale deploy); a later call tries that one again.
 */
export function loadWaveModels(names: readonly WavesChoice[]): Promise<void> {
  return Promise.all(
    modelsMissing(names).map((name) => {
      let load = loads.get(name);
      if (!load) {
        load = LOADERS[name]().then(
          (maker) => void makers.set(name, maker),
          (error: unknown) => {
            loads.delete(name);
            throw error;
          },
        );
        loads.set(name, load);
      }
      return load;
    }),
  ).then(() => undefined);
}

/** A view of `params.waves`; its code must have been loaded (loadWaveModels). */
export function createWaveModelView(params: OceanParams, renderer: WebGLRenderer): WaveModelView {
  const make = makers.get(params.waves);
  if (!make) throw new Error(`The code of wave model '${params.waves}' has not been loaded: call loadWaveModels first.`);
  return make(params, renderer);
}
