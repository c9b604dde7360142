import type { Heightmap } from './perlinNoise';
import type { OceanParams } from './params';
import type { WaveModel } from './waveModel';

/** The `waves` parameter's values: one per registered model. */
export type WavesChoice = OceanParams['waves'];

/**
 * A wave model the app can run: the WaveModel seam plus what a live page needs of it. The
 * model keeps the parameters it is given and reads only those it uses.
 */
export interface LiveWaveModel extends WaveModel {
  readonly name: WavesChoice;
  /** Takes the current parameters; returns true when data the GPU holds (textures) must be made again. */
  setParams(params: OceanParams): boolean;
  /** Height of the displaced surface above the world point (x, z), metres. */
  height(x: number, z: number, time: number): number;
  /**
   * Changes whenever the surface the model answers with may change for any reason but the
   * time asked: its parameters, or data it reads (the FFT twin's fields, computed here or
   * delivered by its Worker). Equal revisions of one model: height(x, z, t) gives the same
   * answer for the same (x, z, t), so a caller may keep it (the boat's pose on a paused view).
   */
  readonly surfaceRevision: number;
  /**
   * Where the model times its CPU twin's work on the calling thread: the ms spent since the
   * last call, counting afresh (FftWaveModel, whose twin has a ≤ 0.1 ms per frame budget).
   */
  takeMainThreadMs?(): number;
  /** Heightmaps the "heightmap" teaching view shows and the API returns, where the model has any. */
  readonly heightmaps?: readonly Heightmap[];
}
