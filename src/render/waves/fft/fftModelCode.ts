import type { WebGLRenderer } from 'three';
import type { OceanParams } from '../../../sim/params/params';
import { FftWaveModel } from '../../../sim/waves/fft/fftWaveModel';
import { FftWaveView } from './fftWaveView';

/**
 * The spectral sea's code, CPU twin and GPU half together: a chunk of its own that the page
 * fetches only when `waves=fft` or a comparison asks for it (registry.ts), so the default
 * view's first frame does not wait for its FFT passes, spectra and worker glue.
 */
export function makeFftWaveView(params: OceanParams, renderer: WebGLRenderer): FftWaveView {
  return new FftWaveView(new FftWaveModel(params), renderer);
}
