import type { OceanParams } from '../../../sim/params/params';
import { GerstnerLiveModel } from '../../../sim/waves/gerstner/gerstnerLiveModel';
import { GerstnerWaveView } from './gerstnerWaveView';

/**
 * Gerstner's trochoids, CPU twin and GPU half together: a chunk of its own, fetched only when
 * `waves=gerstner` or a comparison asks for it (registry.ts).
 */
export function makeGerstnerWaveView(params: OceanParams): GerstnerWaveView {
  return new GerstnerWaveView(new GerstnerLiveModel(params));
}
