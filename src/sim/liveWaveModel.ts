import type { Heightmap } from './perlinNoise';
import type { OceanParams } from './params';
import type { WaveModel } from './waveModel';

/**
 * How a CPU twin's Worker hands its data to the main thread. 'shared-memory': on a
 * cross-origin isolated page, no message per frame (SharedFieldSource); 'messages': anywhere
 * else, a request and a reply per frame (WorkerFieldSource).
 */
export type TwinTransport = 'shared-memory' | 'messages';

/** A CPU twin fed by a Worker, as seen from the main thread (stats().twin). */
export interface TwinStatus {
  /** How the Worker hands its data over; null when there is no Worker (the twin computes on the main thread). */
  transport: TwinTransport | null;
  /** Data sets adopted from the Worker since it started. */
  fieldsReceived: number;
  /** The time of the data the twin holds now (s); NaN before any. */
  fieldsTime: number;
}

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
  /** Where the model's CPU twin gets its data from a Worker: how, and how much has arrived (FftWaveModel). */
  twinStatus?(): TwinStatus;
  /** Heightmaps the "heightmap" teaching view shows and the API returns, where the model has any. */
  readonly heightmaps?: readonly Heightmap[];
}
