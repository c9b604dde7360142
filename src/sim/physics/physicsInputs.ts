import type { OceanParams } from '../params/params';
import { compareModelNames } from '../compare/compareLayout';
import type { SeaParams } from '../waves/spectra/seaState';
import type { GerstnerSeaParams } from '../waves/gerstner/gerstnerLiveModel';
import type { SeedWaveParams } from '../waves/seed/seedWaveModel';

/**
 * The parameters the physics report's figures depend on: every one the three models' heights
 * are drawn from (their own Pick<> types), the model drawn, and the glint's roughness switch.
 * The rest (sun, camera, colours, foam, the panel's own switch) leave the measurement as it is,
 * so changing them costs no new measurement (10 to 40 s of CPU on a slow machine).
 */
const MEASURED_KEYS = [
  'waves',
  'windSpeed',
  'windDirection',
  'spectrum',
  'fetch',
  'depth',
  'spreading',
  'spreadingModel',
  'choppiness',
  'fftSize',
  'seed',
  'gerstnerCount',
  'gerstnerSteepness',
  'swellAmplitude',
  'swellFrequency',
  'rippleStrength',
  'rippleBlendSpeed',
  'seaRoughness',
] as const satisfies readonly (keyof OceanParams)[];

/** Compile-time check: a parameter a model reads that the list above lacks is a type error here. */
type ModelInputs = keyof SeaParams | keyof GerstnerSeaParams | keyof SeedWaveParams;
const listsEveryModelInput: ModelInputs extends (typeof MEASURED_KEYS)[number] ? true : never = true;
void listsEveryModelInput;

/**
 * A key that changes exactly when the physics panel's figures would: two parameter sets with
 * the same key measure the same sea. With the side-by-side split on, the first model named is
 * the one measured (it replaces `waves`).
 */
export function physicsInputs(params: OceanParams): string {
  const shown = compareModelNames(params.compare)[0] ?? params.waves;
  return JSON.stringify(MEASURED_KEYS.map((key) => (key === 'waves' ? shown : params[key])));
}
