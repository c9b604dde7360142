import { FftOcean, type CascadeFields } from './fftOcean';
import type { LiveWaveModel } from '../waveModel';
import type { TwinStatus } from './twinStatus';
import type { OceanParams } from '../../params/params';
import { seaStateFromParams, type SeaState } from '../spectra/seaState';
import { undoHorizontalDisplacement, type DisplacementBounds, type SurfaceSample } from '../waveModel';
import { cascadeSpread } from '../spectra/spectralBounds';

/** Fixed-point steps of the inversion (FftWaveModel.invert); see there for the measured errors. */
export const INVERSION_STEPS = 12;
/**
 * The inversion stops before INVERSION_STEPS once a step moves the grid point by this much or
 * less (metres): most points of a calm sea settle in 5 to 7 steps. The worst height error over
 * 3000 random points (seed 7, against 30 steps) is the same as with 12 steps every time:
 * 3.3e-7 m at U = 10, 2.0e-5 m at U = 20, λ = 1.2; the mean step count falls from 12 to 6.8
 * and 8.1 (fftSize 128).
 */
export const INVERSION_TOLERANCE = 1e-6;

/** The parameters the spectral sea reads; everything else leaves it unchanged. */
export type FftWaveParams = Pick<
  OceanParams,
  'seed' | 'windSpeed' | 'windDirection' | 'spectrum' | 'fetch' | 'depth' | 'spreading' | 'spreadingModel' | 'choppiness' | 'fftSize'
>;

/** A key that changes exactly when the drawn sea changes (JSON of the SeaState; Infinity is spelt out). */
export function seaKey(sea: SeaState): string {
  return JSON.stringify({ ...sea, depth: String(sea.depth) });
}

/**
 * Where fields for a time come from when the main thread must not compute them: a Worker
 * running the same FftOcean (src/render/waves/fft/fftFieldsWorker.ts). request(t) asks for
 * the fields at t; the answer arrives later through FftWaveModel.receive.
 */
export interface FieldSource {
  request(sea: SeaState, time: number): void;
  /**
   * Arrays the model no longer reads (fields it replaced or refused), for the source to fill
   * again: a Worker gets them back (transferred) instead of allocating new ones for every reply.
   */
  recycle?(fields: CascadeFields[]): void;
  dispose(): void;
}

/**
 * The largest step between two successive frame times that still counts as playing. A larger
 * jump (a seek, a paused setTime, the first frame) is computed at once on the calling thread,
 * so a frozen time is always exact. Longer than any step the frame loop's clock takes (at most
 * 0.1 s a frame, src/app/time/simulationClock.ts), with room for float64 sums of those steps, as
 * BoatMotion's maxStep: at exactly 0.1, a loop slower than 10 frames/s took steps of 0.1
 * plus an ulp on most frames, and each computed all the cascades' FFTs on the main thread
 * instead of asking the Worker.
 */
export const MAX_FRAME_STEP = 0.25;

/** Fields older than this are not used even while playing (a Worker that died or fell far behind): compute instead. */
export const MAX_LAG_SECONDS = 1;

/**
 * The spectral sea as the app's LiveWaveModel: the CPU twin (FftOcean, float64 fields read
 * exactly as the GPU reads its textures) plus the policy of when to compute them.
 *
 * Synchronous. `sample` (the API's sampleSurface) and `displacement` are always exact at the
 * time asked: if the fields held are for another time they are computed on the calling thread
 * first (tens of ms). `height` (the frame loop's question: boat, underwater switch) is exact
 * too except while the clock plays with a Worker attached (successive times less than
 * MAX_FRAME_STEP apart): then it answers from the newest fields the Worker has delivered,
 * typically a frame or two old (as old as the Worker's FFTs take), and asks it for the
 * current time. The main thread then spends only bilinear reads per frame on the twin.
 */
export class FftWaveModel implements LiveWaveModel {
  readonly name = 'fft' as const;
  ocean: FftOcean;
  private key: string;
  private source: FieldSource | null = null;
  private lastFrameTime = Number.NaN;
  /** Fields adopted from the source since it was attached (twinStatus). */
  private fieldsReceived = 0;
  /** Milliseconds the calling thread spent in this model (and in work reported by addMainThreadMs) since takeMainThreadMs. */
  private busyMs = 0;

  /**
   * `now`: the clock that times the calling thread's work (ms), performance.now() unless a
   * test gives another.
   */
  constructor(
    params: FftWaveParams,
    private readonly now: () => number = () => performance.now(),
  ) {
    const sea = seaStateFromParams(params);
    this.key = seaKey(sea);
    this.ocean = new FftOcean(sea);
  }

  get sea(): SeaState {
    return this.ocean.setup.sea;
  }

  /** See LiveWaveModel: the fields' revision (a new sea is a new FftOcean, whose fields have a revision of their own). */
  get surfaceRevision(): number {
    return this.ocean.fieldsRevision;
  }

  /** Returns true when the sea changed (a new h₀: the GPU spectrum textures must be made again). */
  setParams(params: FftWaveParams): boolean {
    const sea = seaStateFromParams(params);
    const key = seaKey(sea);
    if (key === this.key) return false;
    this.key = key;
    this.ocean = new FftOcean(sea);
    return true;
  }

  attachSource(source: FieldSource | null): void {
    this.source?.dispose();
    this.source = source;
    this.fieldsReceived = 0;
  }

  /** See LiveWaveModel.twinStatus. */
  twinStatus(): TwinStatus {
    return { fieldsReceived: this.fieldsReceived, fieldsTime: this.ocean.fieldsTime };
  }

  /**
   * Fields a FieldSource computed for `sea` at `time`; ignored if the sea changed meanwhile or
   * they are older than those held.
   */
  receive(sea: SeaState, time: number, fields: CascadeFields[]): void {
    const held = this.ocean.fieldsTime;
    // The source hands back the sea object it was asked about: the same object is the same sea,
    // with no key string built (garbage every frame, so a share of the collections would start
    // inside the twin's timed work).
    const sameSea = sea === this.sea || seaKey(sea) === this.key;
    const refused = !sameSea || (!Number.isNaN(held) && time <= held);
    // The arrays no longer read (the reply refused, or the fields it replaces) go back to the
    // source to be filled again; the model keeps no reference to them.
    const unread = refused ? fields : this.ocean.adoptFields(time, fields);
    this.source?.recycle?.(unread);
    if (!refused) this.fieldsReceived++;
  }

  /** The time whose fields answer a question about `time` (see the class comment). */
  private fieldsFor(time: number, exact: boolean): number {
    const held = this.ocean.fieldsTime;
    const previous = this.lastFrameTime;
    if (!exact) this.lastFrameTime = time;
    if (time === held) return time;
    const playing =
      !exact && this.source !== null && Math.abs(time - previous) <= MAX_FRAME_STEP && Math.abs(time - held) <= MAX_LAG_SECONDS;
    if (playing) {
      this.source?.request(this.sea, time);
      return this.ocean.fieldsTime;
    }
    this.ocean.setTime(time);
    return time;
  }

  /** See LiveWaveModel: the time of the fields height() answers from, asked about the frame at `time`. */
  frameDataTime(time: number): number {
    const start = this.now();
    const at = this.fieldsFor(time, false);
    this.busyMs += this.now() - start;
    return at;
  }

  /** Asks the Worker (if any) for the fields at `time` ahead of use: called once per frame. */
  prefetch(time: number): void {
    const start = this.now();
    if (this.source && time !== this.ocean.fieldsTime) this.source.request(this.sea, time);
    this.busyMs += this.now() - start;
  }

  /** Counts work done for this model outside its methods (receiving the Worker's message: FieldSource). */
  addMainThreadMs(ms: number): void {
    this.busyMs += ms;
  }

  /**
   * The calling thread's time in this model since the last call (ms), and starts counting
   * afresh: surface questions (height, sample, displacement), the Worker requests, and the
   * replies reported through addMainThreadMs. The app takes it once per frame (stats().twinMs).
   */
  takeMainThreadMs(): number {
    const ms = this.busyMs;
    this.busyMs = 0;
    return ms;
  }

  displacement(x: number, z: number, time: number): [number, number, number] {
    const start = this.now();
    const d = this.ocean.displacement(x, z, this.fieldsFor(time, true));
    this.busyMs += this.now() - start;
    return d;
  }

  /**
   * The grid point p whose vertex lands above the world point q = (x, z), and its height:
   * p + D(p) = q by the seam's fixed-point iteration p ← q − D(p), which converges at the
   * rate |∂D/∂x|. A choppy gale pushes that rate near 1, so this model takes more steps than
   * the seam's default 4. Worst height error over 3000 random points, seed 7 (measured,
   * scripts of this commit): U = 10, λ = 1: 4 steps 1.7 mm, 8 steps 2e-5 m, 12 steps 4e-7 m;
   * U = 20, λ = 1.2: 4 steps 2.1 cm, 8 steps 0.6 mm, 12 steps 1.8e-5 m. (Newton's method with
   * the spectral Jacobian did worse, 1.4 cm in 3 steps: the bilinear fields' slopes are not
   * the spectral ones.) A point that settles sooner stops there (INVERSION_TOLERANCE).
   */
  invert(x: number, z: number, at: number): { x: number; z: number; height: number; residual: number } {
    const p = undoHorizontalDisplacement((px, pz) => this.ocean.displacement(px, pz, at), x, z, INVERSION_STEPS, INVERSION_TOLERANCE);
    return { x: p.x, z: p.z, height: this.ocean.displacement(p.x, p.z, at)[1], residual: p.residual };
  }

  /** The height alone (the inversion without the normal); lags while playing, see the class comment. */
  height(x: number, z: number, time: number): number {
    const start = this.now();
    // invert(…).height, bit for bit, reading only the channels it uses (FftOcean.heightAt).
    const h = this.ocean.heightAt(x, z, this.fieldsFor(time, false), INVERSION_STEPS, INVERSION_TOLERANCE);
    this.busyMs += this.now() - start;
    return h;
  }

  sample(x: number, z: number, time: number): SurfaceSample {
    const start = this.now();
    const s = this.sampleScratch;
    this.ocean.sampleInto(x, z, this.fieldsFor(time, true), INVERSION_STEPS, INVERSION_TOLERANCE, s, 0);
    this.busyMs += this.now() - start;
    return { height: s[0], normal: [s[1], s[2], s[3]] };
  }

  /**
   * sample() for many points at once (sampleSurfaces): points[2i], points[2i + 1] are world
   * x, z (metres); out[4i..4i+3] receives the height (metres) and the unit normal, each equal
   * to sample()'s. One time for all, so the fields are looked up once.
   */
  sampleMany(points: ArrayLike<number>, time: number, out: { [i: number]: number }): void {
    const start = this.now();
    const at = this.fieldsFor(time, true);
    this.ocean.sampleManyInto(points, at, INVERSION_STEPS, INVERSION_TOLERANCE, out);
    this.busyMs += this.now() - start;
  }

  private readonly sampleScratch = new Float64Array(4);

  /** The sea the slope variance was summed for, and the sum. */
  private slopes: { ocean: FftOcean; variance: number } | null = null;

  /** See LiveWaveModel: every cascade's realised mean-square slope (i k h₀ over its tile), summed. */
  slopeVariance(): number {
    if (this.slopes?.ocean !== this.ocean) {
      const { sea, tiles } = this.ocean.setup;
      const variance = tiles.reduce((sum, tile) => sum + cascadeSpread(tile, sea.depth).slope ** 2, 0);
      this.slopes = { ocean: this.ocean, variance };
    }
    return this.slopes.variance;
  }

  bounds(): DisplacementBounds {
    return this.ocean.bounds();
  }

  dispose(): void {
    this.attachSource(null);
  }
}
