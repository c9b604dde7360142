/**
 * Oceano as a library (`import { Ocean } from 'oceano'`): the ocean as a three.js object for
 * scenes of your own, and its optional underwater passes. three.js is a peer dependency.
 */
export { Ocean, type OceanOptions } from './render/ocean/ocean';
export { OceanUnderwater, type OceanUnderwaterOptions } from './render/underwater/oceanUnderwater';
export { OceanUnderwaterPass, type OceanUnderwaterPassOptions } from './render/underwater/oceanUnderwaterPass';
export type { EncodedScene } from './render/underwater/underwaterPost';
export {
  defaultOceanOptions,
  oceanOptionDefs,
  validateOceanOptions,
  type OceanParameters,
  type OceanParamKey,
} from './sim/params/oceanOptionKeys';
export type { SurfaceSample, LiveWaveModel, WavesChoice } from './sim/waves/waveModel';
export type { SampleSurfacesOptions, SurfacePoints, SurfaceSamples } from './sim/waves/surfaceBatch';
export type { Submersion } from './sim/underwater/snellWindow';
