import type { OceanApp, BoatInfo, CameraPose, LoopActivity, OceanStats } from '../oceanApp';
import type { OceanParams } from '../../sim/params/params';
import type { SurfaceSample } from '../../sim/waves/waveModel';
import type { PhysicsReport } from '../../sim/physics/physicsReport';
import type { ProbeSample } from '../../render/teaching/surfaceProbe';
import type { OceanView } from '../../render/ocean/oceanView';
import type { DebugTools } from '../debug/debugTools';
import type { ProbeReading } from '../tools/probeTool';

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
  /** Pauses and advances one frame of 1/60 s times timeScale, then draws it: the frame playing at 60 fps draws next. */
  step(): void;
  renderFrame(): void;
  getParams(): OceanParams;
  setParams(partial: Partial<OceanParams>): OceanParams;
  setCamera(pose: CameraPose): void;
  getCamera(): CameraPose;
  /** The surface as drawn at the current time: the active waves plus the boat's wake where it is on. */
  sampleSurface(x: number, z: number): SurfaceSample;
  /** The still water's depth at world (x, z), metres, from the sea floor in force (`bathymetry`): ≤ 0 on land. */
  depth(x: number, z: number): number;
  /** The same surface evaluated by the GPU shader and read back; `t` defaults to the current time. */
  probeGpu(points: [number, number][], t?: number): Promise<ProbeSample[]>;
  /**
   * Drops a stone into the interactive waves (interactiveWaves on) at world (x, z): a bump of
   * `height` m (default 0.3, negative for a dip) and `radius` m (default 1). Bad arguments throw
   * and change nothing; returns notices (a radius under one texel is raised to one texel). The
   * page shows either in a notice too, in its language.
   */
  disturb(x: number, z: number, options?: { radius?: number; height?: number }): string[];
  /**
   * The probe of the sea tools (src/app/tools/): probe(x, z) places it at world (x, z), probe()
   * reads it, probe(null) removes it. Each answers its reading (null without a probe): the last
   * 30 s of heights there, one per drawn frame, Tz, Hs and crest to trough against the model's
   * theory. Async: the tools' code is fetched on first use. Bad arguments reject with a TypeError.
   */
  probe(...place: [] | [null] | [x: number, z: number]): Promise<ProbeReading | null>;
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
  /** The lessons in the course's order, in the page's language (src/app/lessons/lessonCatalog.ts); `exercise`: the card has a measurement to make. */
  lessons(): { id: string; title: string; section: string; question: boolean; exercise: boolean }[];
  /** The open lesson's id, or null. */
  lesson(): string | null;
  /** Opens a lesson: its view and its card; resolves true. An unknown id shows a notice, changes nothing and resolves false. After `ready` the view has changed when this returns. */
  setLesson(id: string): Promise<boolean>;
  /** The link that reopens this view exactly (what the share button copies). */
  shareUrl(): string;
  /** Whether the frame loop runs (it stops off screen and in hidden tabs) and frames drawn so far. */
  activity(): LoopActivity;
  /**
   * Diagnostics and negative controls (src/app/debug/): fetched on first use, so every call
   * answers a promise. fresnelTable, fresnelTableFromBelow (n₁ = 1.333, n₂ = 1); passTimings
   * (one frame drawn waiting for the GPU after each pass: 'scene', or 'scene <model> strip' per
   * compare strip, after a model's own passes); heightmaps; lodUpdateMs (median CPU ms of one
   * LOD/culling update, batches of 20); frameCounts (one frame's draw calls, passes, program
   * switches and bytes uploaded, counted from its WebGL calls); forceShaftLightWindow; setShadingFixes (turn off fixes
   * for far and very close views); stripCulling (compare= strips drawing only the tiles that
   * reach them); underwaterScene (the underwater passes' scene target, 'linear' or encoded).
   */
  debug: Promisified<DebugTools> & {
    /** How many times the physics estimators have run, once the open panel has drawn. */
    physicsRuns(): Promise<number>;
  };
  readonly three: Pick<OceanView, 'renderer' | 'scene' | 'camera'>;
}

/** Each method of T, answering a promise of what it returned. */
type Promisified<T> = { [K in keyof T]: T[K] extends (...args: infer A) => infer R ? (...args: A) => Promise<Awaited<R>> : never };

/** The calls of `oceano.debug` that live in src/app/debug/debugTools.ts, each named once here. */
const DEBUG_CALLS = [
  'fresnelTable',
  'fresnelTableFromBelow',
  'passTimings',
  'heightmaps',
  'lodUpdateMs',
  'frameCounts',
  'forceShaftLightWindow',
  'setShadingFixes',
  'foamMemory',
  'prefilteredSkyPaints',
  'stripCulling',
  'underwaterScene',
] as const satisfies readonly (keyof DebugTools)[];
// Fails to compile while a call of debugTools.ts is missing from the list.
const EVERY_DEBUG_CALL: Exclude<keyof DebugTools, (typeof DEBUG_CALLS)[number]> extends never ? true : never = true;
void EVERY_DEBUG_CALL;

/** Each of `oceano.debug`'s calls answering `answer(name)`. */
function debugCalls(answer: (name: keyof DebugTools) => (...args: never[]) => Promise<unknown>): Promisified<DebugTools> {
  return Object.fromEntries(DEBUG_CALLS.map((name) => [name, answer(name)])) as Promisified<DebugTools>;
}

/** `oceano.debug`: each call fetches src/app/debug/debugTools.ts the first time, then runs there. */
function lazyDebugTools(app: OceanApp): Promisified<DebugTools> {
  let tools: Promise<DebugTools> | undefined;
  const load = () => (tools ??= import('../debug/debugTools').then((code) => code.debugTools(app)));
  return debugCalls(
    (name) =>
      (...args: unknown[]) =>
        load().then((t) => (t[name] as (...a: unknown[]) => unknown)(...args)),
  );
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
    step: () => app.step(),
    renderFrame: () => app.renderFrame(true),
    loaded: () => app.whenPartsLoaded().then(() => app.renderFrame(true)),
    getParams: () => app.getParams(),
    setParams: (partial) => app.setParams(partial),
    setCamera: (pose) => app.setCamera(pose),
    getCamera: () => app.camera(),
    sampleSurface: (x, z) => app.sampleSurface(x, z),
    depth: (x, z) => app.depth(x, z),
    probeGpu: async (points, t) => app.probeGpu(points, t),
    disturb: (x, z, options) => app.disturb(x, z, options),
    probe: (...place) => app.loadSeaTools().then((tools) => tools.probeCall(place)),
    boat: () => app.boat(),
    stats: () => app.stats(),
    physics: async () => (await started(app.physicsPanel())).measure(),
    notices: () => app.notices.messages(),
    lessons: () => app.lessonList(),
    lesson: () => app.lesson(),
    setLesson: (id) => app.openLesson(id),
    shareUrl: () => app.shareUrl(),
    activity: () => app.activity(),
    debug: {
      ...lazyDebugTools(app),
      physicsRuns: async () => {
        const panel = await started(app.physicsPanel());
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
  const failed = () => Promise.reject(reason);
  return {
    ready,
    setTime: fail,
    play: fail,
    pause: fail,
    step: fail,
    renderFrame: fail,
    loaded: () => ready,
    getParams: fail,
    setParams: fail,
    setCamera: fail,
    getCamera: fail,
    sampleSurface: fail,
    depth: fail,
    probeGpu: () => Promise.reject(reason),
    disturb: fail,
    probe: failed,
    boat: fail,
    stats: fail,
    notices: fail,
    lessons: fail,
    lesson: fail,
    setLesson: failed,
    shareUrl: fail,
    activity: fail,
    physics: () => Promise.reject(reason),
    debug: {
      ...debugCalls(() => failed),
      physicsRuns: failed,
    },
    get three(): never {
      throw reason;
    },
  };
}
