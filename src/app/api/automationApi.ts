import type { OceanApp, BoatInfo, CameraPose, LoopActivity, OceanStats } from '../oceanApp';
import type { OceanParams } from '../../sim/params/params';
import type { SurfaceSample } from '../../sim/waves/waveModel';
import type { PhysicsReport } from '../../sim/physics/physicsReport';
import type { ProbeSample } from '../../render/teaching/surfaceProbe';
import type { PassTiming } from '../../render/underwater/underwaterPost';
import type { OceanView, ShadingFixes } from '../../render/ocean/oceanView';
import { checkBatches } from './apiChecks';

/**
 * `window.oceano` on the page, `element.oceano` on an <oceano-view>: how tests, course
 * pages and the console drive one ocean.
 */
export interface OceanoApi {
  /** Resolves once the first frame is drawn and the boat is in it (or a notice says why it is not). */
  ready: Promise<void>;
  /**
   * Settles once every part loaded on first use that the view has asked for (a wave model's
   * code after setParams({ waves }) or { compare }; the underwater passes, on the first frame
   * below the surface) has arrived, and a frame with it is drawn.
   */
  loaded(): Promise<void>;
  setTime(seconds: number): void;
  play(): void;
  pause(): void;
  renderFrame(): void;
  getParams(): OceanParams;
  setParams(partial: Partial<OceanParams>): OceanParams;
  setCamera(pose: CameraPose): void;
  getCamera(): CameraPose;
  /** The surface as drawn at the current time: the active waves plus the boat's wake where it is on. */
  sampleSurface(x: number, z: number): SurfaceSample;
  /** The same surface evaluated by the GPU shader and read back; `t` defaults to the current time. */
  probeGpu(points: [number, number][], t?: number): Promise<ProbeSample[]>;
  /** The boat's pose: position in metres, heading, pitch and roll in radians (conventions in src/sim/boat/boatPose.ts). */
  boat(): BoatInfo;
  stats(): OceanStats;
  /**
   * The running sea measured through its CPU twin against theory (the physics panel's
   * figures), from the time of the call. Takes seconds; async because the estimators' code
   * is fetched on first use.
   */
  physics(): Promise<PhysicsReport>;
  notices(): string[];
  /** The link that reopens this view exactly (what the share button copies). */
  shareUrl(): string;
  /** Whether the frame loop runs (it stops off screen and in hidden tabs) and frames drawn so far. */
  activity(): LoopActivity;
  debug: {
    fresnelTable(): Float32Array;
    /** The reflectance table seen from under the water (n₁ = 1.333, n₂ = 1). */
    fresnelTableFromBelow(): Float32Array;
    /** Draws one frame, waiting for the GPU after each pass; each pass's cost in ms ('scene' alone above the water, or 'scene <model> strip' per compare strip, after 'fft' and 'foam' when a model is fft). */
    passTimings(): PassTiming[];
    heightmaps(): { size: number; data: Float32Array }[];
    /** Median CPU ms of one LOD/culling update for the current camera (batches of 20 updates). */
    lodUpdateMs(batches?: number): number;
    /** Under the water: bake the shaft light as the window generic wave models get, even for the seed. */
    forceShaftLightWindow(on: boolean): void;
    /** Negative controls: turn off fixes for far and very close views (see OceanView.setShadingFixes). */
    setShadingFixes(fixes: Partial<ShadingFixes>): void;
    /** compare=: whether each strip draws a chunk straddling it as only the tiles that reach it (on by default; off to measure what that saves). */
    stripCulling(on: boolean): void;
    /** How many times the physics estimators have run, once the open panel has drawn. */
    physicsRuns(): Promise<number>;
  };
  readonly three: Pick<OceanView, 'renderer' | 'scene' | 'camera'>;
}

declare global {
  interface Window {
    oceano: OceanoApi;
  }
}

/** The physics panel exists once the app has started (after `ready`). */
function started<T>(part: T | undefined): T {
  if (part === undefined) throw new Error('The ocean has not started yet: await oceano.ready first.');
  return part;
}

export function createAutomationApi(app: OceanApp, ready: Promise<void>): OceanoApi {
  return {
    ready,
    setTime: (seconds) => app.setTime(seconds),
    play: () => app.play(),
    pause: () => app.pause(),
    renderFrame: () => app.renderFrame(true),
    loaded: () => app.whenPartsLoaded().then(() => app.renderFrame(true)),
    getParams: () => app.getParams(),
    setParams: (partial) => app.setParams(partial),
    setCamera: (pose) => app.setCamera(pose),
    getCamera: () => app.camera(),
    sampleSurface: (x, z) => app.sampleSurface(x, z),
    probeGpu: async (points, t) => app.probeGpu(points, t),
    boat: () => app.boat(),
    stats: () => app.stats(),
    physics: async () => started(app.physicsPanel()).measure(),
    notices: () => app.notices.messages(),
    shareUrl: () => app.shareUrl(),
    activity: () => app.activity(),
    debug: {
      fresnelTable: () => app.debugView().fresnelData.slice(),
      fresnelTableFromBelow: () => app.debugView().fresnelFromBelowData.slice(),
      passTimings: () => app.debugView().profileFrame(app.clock.time),
      heightmaps: () => (app.debugView().waves.heightmaps ?? []).map((map) => ({ size: map.size, data: map.data.slice() })),
      lodUpdateMs: (batches) => app.debugView().timeLodUpdate(checkBatches(batches)),
      forceShaftLightWindow: (on) => app.debugView().forceShaftLightWindow(on === true),
      setShadingFixes: (fixes) => app.debugView().setShadingFixes(fixes),
      stripCulling: (on) => {
        app.debugView().stripCulling = on === true;
      },
      physicsRuns: async () => {
        const panel = started(app.physicsPanel());
        await panel.settled();
        return panel.runs;
      },
    },
    get three() {
      const view = app.debugView();
      return { renderer: view.renderer, scene: view.scene, camera: view.camera };
    },
  };
}

/**
 * The API of an ocean that could not start (no WebGL2, a failed boot): `ready` rejects with
 * the reason and every call throws it, so a harness awaiting `ready` fails loudly instead
 * of screenshotting a blank page, and `window.oceano` is never anything but this API.
 */
export function createFailedApi(reason: Error): OceanoApi {
  const ready = Promise.reject(reason);
  // Handled here so the page logs no unhandled rejection; whoever awaits `ready` still gets it.
  ready.catch(() => undefined);
  const fail = (): never => {
    throw reason;
  };
  return {
    ready,
    setTime: fail,
    play: fail,
    pause: fail,
    renderFrame: fail,
    loaded: () => ready,
    getParams: fail,
    setParams: fail,
    setCamera: fail,
    getCamera: fail,
    sampleSurface: fail,
    probeGpu: () => Promise.reject(reason),
    boat: fail,
    stats: fail,
    notices: fail,
    shareUrl: fail,
    activity: fail,
    physics: () => Promise.reject(reason),
    debug: { fresnelTable: fail, fresnelTableFromBelow: fail, passTimings: fail, heightmaps: fail, lodUpdateMs: fail, forceShaftLightWindow: fail, setShadingFixes: fail, stripCulling: fail, physicsRuns: () => Promise.reject(reason) },
    get three(): never {
      throw reason;
    },
  };
}
