import { validateParams, type OceanParams } from '../sim/params/params';
import { message, MessageError, type Message } from '../sim/params/message';
import type { SurfaceSample } from '../sim/waves/waveModel';
import { OceanView } from '../render/ocean/oceanView';
import { BoatView } from '../render/boat/boatView';
import type { ProbeSample } from '../render/teaching/surfaceProbe';
import { DEFAULT_CAMERA, type CameraPose } from './camera/cameraPose';
import { Translator } from './language/i18n';
import type { Notices } from './boot/notices';
import { SimulationClock } from './time/simulationClock';
import type { OceanAppOptions } from './boot/appOptions';
import { buildScaffold, disposeScaffold, labelCanvas, type Scaffold } from './boot/appScaffold';
import { FrameLoop, type LoopActivity, type SuspendReason } from './time/frameLoop';
import { FrameStats, type OceanStats } from './time/frameStats';
import { BoatController, type BoatInfo } from './boat/boatController';
import { OrbitCamera } from './camera/orbitCamera';
import { shareLink, shareUrl } from './url/sharing';
import { checkCameraPose, checkProbe, checkSurfacePoint, checkTime } from './api/apiChecks';
import { loadBoatOrNotify, loadCustomSky } from './boot/assetFallbacks';
import { ContextWatch } from './boot/contextLoss';
import { AppControls } from './panel/appControls';
import { loadWaveModels, modelsDrawn, modelsMissing } from '../render/waves/waveViewRegistry';
import { COMPARE_OFF } from '../sim/compare/compareLayout';
import { loadLessonCatalog, loadedLessonCatalog, type LessonCatalog } from './lessons/lessonCatalogLoader';
import { LessonHost } from './lessons/lessonHost';
import { FREE_AREA_EVENT } from './layout/freeAreaEvent';
import type { Rect } from '../sim/layout/rect';
import type { SeaTools } from './tools/seaTools';

export type { OceanAppOptions } from './boot/appOptions';
export type { BoatInfo, CameraPose, LoopActivity, OceanStats, SuspendReason };

/** The shipped model, relative to the page (or to oceano.js for the web component). */
export const DEFAULT_BOAT_MODEL = 'models/boat.glb';

/**
 * Where the page's start-up is marked (`oceano:` marks on the performance timeline): its first
 * ocean's, up to its first frame, and null from then on, since the browser keeps every mark until the page
 * clears it and figures that start again as a page scrolls would add theirs without end.
 */
let startupTimeline: Performance | null = performance;

/**
 * One live ocean in a container element: the composition root. It owns the parameters and the clock and wires
 * the parts, each in a file of its own: the DOM scaffold, FrameLoop, FrameStats, ContextWatch, BoatController,
 * OrbitCamera, sharing, the API's argument checks and the asset fallbacks. The automation API is a thin layer.
 */
export class OceanApp {
  readonly notices: Notices;
  readonly clock: SimulationClock;
  readonly canvas: HTMLCanvasElement;
  readonly tr: Translator;
  private readonly scaffold: Scaffold;
  private params: OceanParams;
  // The view, the boat and the loop are read by the sea tools (src/app/tools/seaTools.ts), a chunk of their own.
  view!: OceanView;
  /** The camera's controls, once started: the element gates their touch gestures (element/touchOrbitGate.ts). */
  orbit!: OrbitCamera;
  boatMotion!: BoatController;
  private context?: ContextWatch;
  private controls?: AppControls;
  private lessons?: LessonHost;
  private resizeObserver?: ResizeObserver;
  private readonly frameStats = new FrameStats();
  readonly loop: FrameLoop;
  /** The probe, ruler and stones, fetched when first used (loadSeaTools). */
  private seaTools?: SeaTools;
  private seaToolsLoad?: Promise<SeaTools>;
  /** The code of wave models asked for at run time, while it is on its way (showParams). */
  private modelLoad?: Promise<void>;
  private started = false;
  private disposed = false;

  constructor(
    readonly container: HTMLElement,
    readonly options: OceanAppOptions,
  ) {
    this.tr = new Translator(options.language);
    this.params = { ...options.state.params };
    this.scaffold = buildScaffold(
      container,
      this.tr,
      this.params,
      () => this.setPlaying(!this.clock.playing),
      options.alt,
      options.onProgress,
    );
    ({ canvas: this.canvas, notices: this.notices } = this.scaffold);
    for (const notice of options.state.notices) this.notify(notice);
    this.clock = new SimulationClock(options.state.time ?? 0, options.state.time === null && !options.reducedMotion);
    this.scaffold.playButton.sync(this.clock.playing);
    const tick = (seconds: number) => {
      this.controls?.steer(Math.min(seconds, SimulationClock.MAX_STEP));
      this.clock.advance(seconds, Number(this.params.timeScale));
      this.renderFrame();
    };
    this.loop = new FrameLoop({ tick, redraw: () => this.renderFrame(), playing: () => this.clock.playing });
  }

  /** Shows a message in the app's language. */
  notify = (m: Message, level: 'warning' | 'error' = 'warning'): HTMLElement => this.notices.show(this.tr.message(m), level);

  /**
   * Builds the scene, draws the first frame and starts the loop, then loads the boat while the sea runs. Resolves
   * once a frame with the boat (or a notice saying why it is missing) is on screen, so `oceano.ready` means finished.
   */
  async start(): Promise<void> {
    const { state, showPanel, skyBase } = this.options,
      { loading } = this.scaffold;
    const [sky] = await Promise.all([loadCustomSky(skyBase, state.sky, this.notify), this.loadStartModels()]);
    loading.begin('firstFrame');
    await loading.painted();
    if (this.disposed) return sky?.dispose();
    startupTimeline?.mark('oceano:view-start');
    this.view = new OceanView(this.canvas, sky, this.params, this.loop.requestRender, () => this.notify(message('underwaterLoadFailed')));
    startupTimeline?.mark('oceano:view-built');
    this.orbit = new OrbitCamera(this.view.camera, this.canvas, this.loop.requestRender);
    this.container.addEventListener(FREE_AREA_EVENT, this.onFreeArea);
    this.boatMotion = new BoatController(
      new BoatView(this.view.scene),
      (dx, dz) => this.orbit.translate(dx, dz),
      state,
      () => void import('./boat/agroundNotice').then(({ agroundNotice }) => this.notify(agroundNotice)),
    );
    this.view.ocean.recordStones(state.stones);
    if (state.cullingCamera && this.params.freezeCulling) {
      // freeze the selection from the culling camera, then look at it from the preset's
      this.orbit.setPose(state.cullingCamera);
      this.view.update(this.clock.time);
    }
    if (state.camera) this.orbit.setPose(state.camera);
    this.context = new ContextWatch(this.view.renderer, {
      showNotice: () => this.notify(message('contextLost'), 'error'),
      removeNotice: (notice) => this.notices.remove(notice),
      setLost: (lost) => this.loop.setStopped('contextLost', lost),
      redraw: () => (this.view.contextRestored(), this.resize(), this.renderFrame()),
    });
    const physics = {
      model: () => this.view.waves,
      params: () => this.params,
      time: () => this.clock.time,
      modelsLoaded: async () => {
        while (this.modelLoad) await this.modelLoad;
      },
    };
    this.controls = new AppControls(
      this.container,
      this.view.ocean.fresnelData,
      {
        showPanel,
        params: this.params,
        playing: this.clock.playing,
        tr: this.tr,
        physics,
        panelFailed: () => this.notify(message('panelLoadFailed')),
      },
      this,
      {
        onParam: (key, value) => this.setParams({ [key]: value }),
        onPlayingChange: (playing) => this.setPlaying(playing),
        onShare: () => void this.share(),
        onDive: () => this.orbit.dive(),
        onStep: () => this.step(),
        onSurface: () => this.orbit.setPose(DEFAULT_CAMERA),
        onSeaTools: this.loadSeaTools,
      },
    );
    this.lessons = new LessonHost(this.container, this.tr, showPanel, this.params, {
      openLesson: (id) => this.openLesson(id),
      onParam: (key, value) => this.setParams({ [key]: value }),
      openFolders: (keys) => this.controls?.openFoldersOf(keys),
      scene: () => ({
        camera: this.view.camera,
        pose: this.orbit.pose(),
        canvas: this.canvas,
        time: this.clock.time,
        boat: this.boatMotion.info(),
        height: (x, z) => this.view.waves.height(x, z, this.clock.time),
        stoneDropped: this.view.ocean.interactiveWaves?.stones(this.clock.time, Number.POSITIVE_INFINITY).at(-1)?.[0] ?? null,
      }),
    });
    if (state.lesson) this.lessons.current = state.lesson;
    startupTimeline?.mark('oceano:controls');
    this.resize();
    (this.resizeObserver = new ResizeObserver(() => this.resize())).observe(this.canvas);
    this.started = true;
    this.renderFrame(true);
    this.frameStats.markFirstFrame();
    startupTimeline?.mark('oceano:first-frame');
    startupTimeline = null;
    this.options.onFirstFrame?.();
    this.loop.start();
    // The panel's code (lil-gui) comes after the first frame, beside the boat: `ready` still means the page is complete.
    const [model] = await Promise.all([
      loadBoatOrNotify(this.options.boatUrl, this.notify, loading),
      this.view.whenPartsLoaded(),
      this.controls.loadPanel(),
      this.controls.whenPartsLoaded(),
      this.lessons.load(),
      loadLessonCatalog(),
      this.orbit.loaded,
      state.probe !== null && this.loadSeaTools(),
    ]);
    if (model) this.view.lightWithCaustics(model.object);
    this.boatMotion.setModel(model);
    this.renderFrame(true);
    loading.finish();
  }

  /**
   * The code of the models the starting parameters draw (waves=fft, gerstner, compare=), in
   * parallel with a page's own sky. Where it cannot be fetched: a notice, and the seed's sea.
   */
  private async loadStartModels(): Promise<void> {
    const wanted = modelsDrawn(this.params);
    try {
      await loadWaveModels(wanted);
    } catch (error) {
      console.warn("Oceano: a wave model's code could not be loaded.", error);
      this.notify(message('modelLoadFailed', { name: modelsMissing(wanted).join(', '), fallback: 'seed' }));
      this.params = { ...this.params, waves: 'seed', compare: COMPARE_OFF };
    }
  }

  /**
   * Shows the parameters. A model whose code has not arrived yet is fetched first: meanwhile
   * the view keeps the models it shows and takes every other change now; if the code cannot
   * be had, a notice says so and the parameters go back to the models shown.
   */
  private showParams(): void {
    const missing = modelsMissing(modelsDrawn(this.params));
    if (missing.length === 0) {
      this.modelLoad = undefined;
      this.view.applyParams(this.params);
      return;
    }
    const shown = this.view.shownModels();
    this.view.applyParams({ ...this.params, ...shown });
    const load: Promise<void> = loadWaveModels(missing).then(
      () => {
        if (this.modelLoad !== load || this.disposed) return;
        this.modelLoad = undefined;
        this.view.applyParams(this.params);
        this.loop.requestRender();
      },
      (error: unknown) => {
        if (this.modelLoad !== load || this.disposed) return;
        this.modelLoad = undefined;
        console.warn("Oceano: a wave model's code could not be loaded.", error);
        this.notify(message('modelLoadFailed', { name: missing.join(', '), fallback: modelsDrawn(shown).join(', ') }));
        this.params = { ...this.params, ...shown };
        labelCanvas(this.canvas, this.tr, this.params, this.options.alt);
        this.controls?.sync(this.params, this.clock.playing);
        this.loop.requestRender();
      },
    );
    this.modelLoad = load;
  }

  /**
   * Settles once every part fetched on first use has arrived (a wave model's code asked for by
   * setParams, the underwater passes) and is in the view.
   */
  async whenPartsLoaded(): Promise<void> {
    while (this.modelLoad) await this.modelLoad;
    await this.view.whenPartsLoaded();
    await this.controls?.whenPartsLoaded();
  }

  /** Stops the frame loop while the tab is hidden or the view is scrolled away; a page of many views stays light. */
  setSuspended = (reason: SuspendReason, suspended: boolean): void => this.loop.setStopped(reason, suspended);
  isStarted = (): boolean => this.started && !this.disposed;
  activity = (): LoopActivity => ({ looping: this.loop.isLooping, framesDrawn: this.frameStats.framesDrawn });

  /** The panels moved or resized (src/app/layout/freeArea.ts): the compare strips and teaching views are laid out again. */
  private readonly onFreeArea = (event: Event): void => {
    this.view.setFreeArea((event as CustomEvent<Rect>).detail);
    this.loop.requestRender();
  };

  /** Resizing clears the canvas, so a paused view draws again. */
  private resize(): void {
    const rect = this.canvas.getBoundingClientRect();
    this.view.setSize(rect.width, rect.height, Math.min(window.devicePixelRatio, 2));
    this.loop.requestRender();
  }

  /** Draws one frame at the clock's time; `sync` waits for the GPU so frameMs counts GPU work (see FrameStats). */
  renderFrame(sync = this.frameStats.loopShouldSync()): void {
    if (this.context?.lost) return;
    const start = performance.now();
    this.boatMotion.update(this.clock.time, this.params, this.view.waves, this.view, this.view.ocean);
    const boatEnd = performance.now();
    startupTimeline?.mark('oceano:first-boat-update');
    this.view.update(this.clock.time);
    this.frameStats.recordUpdate(boatEnd - start, performance.now() - start);
    startupTimeline?.mark('oceano:first-update');
    this.frameStats.recordTwin(this.view.waves.takeMainThreadMs?.() ?? null);
    this.seaTools?.frame();
    this.view.draw();
    startupTimeline?.mark('oceano:first-draw-submitted');
    this.controls?.showCounts(this.frameStats.framesDrawn++, this.loop.isLooping, () => this.view.stats());
    this.lessons?.afterFrame();
    if (!sync) return;
    this.view.waitForGpu();
    this.frameStats.recordSyncedFrame(performance.now() - start);
  }

  /** Validates the whole update before applying any of it; throws a ParamError naming the bad key. */
  setParams(partial: unknown): OceanParams {
    const valid = validateParams(partial);
    const startsFollowing = valid.boatFollow === true && !this.params.boatFollow;
    this.params = { ...this.params, ...valid };
    if (startsFollowing) this.boatMotion.startFollowing(this.orbit.target);
    this.showParams();
    labelCanvas(this.canvas, this.tr, this.params, this.options.alt);
    this.controls?.sync(this.params, this.clock.playing);
    this.lessons?.sync(this.params);
    this.loop.requestRender();
    return this.getParams();
  }

  private setPlaying(playing: boolean): void {
    this.clock.playing = playing;
    this.controls?.sync(this.params, playing);
    this.scaffold.playButton.sync(playing);
    this.loop.refresh();
  }

  /**
   * Opens a lesson: its view as a preset sets it (the defaults, its parameters, its camera;
   * the clock runs on), then its card. An unknown id changes nothing and says so in a notice.
   * Resolves true once open; the catalog is loaded by `ready`, and from then on the view
   * changes before this returns, so values set right after it override the lesson's.
   */
  openLesson(id: string): Promise<boolean> {
    const catalog = loadedLessonCatalog();
    if (catalog) return Promise.resolve(this.openFromCatalog(catalog, id));
    return loadLessonCatalog().then((loaded) => this.openFromCatalog(loaded, id));
  }

  private openFromCatalog({ findLesson, lessonIds, lessonView }: LessonCatalog, id: string): boolean {
    const lesson = typeof id === 'string' ? findLesson(id) : null;
    if (!lesson) {
      this.notify(message('lessonUnknown', { name: String(id), known: lessonIds.join(', ') }));
      return false;
    }
    const { params, camera, cullingCamera, stones } = lessonView(lesson);
    if (cullingCamera && params.freezeCulling && this.started) {
      // As at start-up: the selection is frozen from the culling camera, then seen from the lesson's.
      this.setParams({ ...params, freezeCulling: false });
      this.orbit.setPose(cullingCamera);
      this.view.update(this.clock.time);
    }
    this.setParams(params);
    if (this.started) {
      this.orbit.setPose(camera);
      // Its stones fall from now on, as the lesson opens.
      this.view.ocean.recordStones(stones, this.clock.time);
    }
    void this.lessons?.show(lesson.id);
    return true;
  }

  lesson = (): string | null => this.lessons?.current ?? this.options.state.lesson;
  lessonList = () => {
    if (!this.lessons) throw new Error('The ocean has not started yet: await oceano.ready first.');
    return this.lessons.titles();
  };

  getParams = (): OceanParams => ({ ...this.params });
  setTime = (seconds: number): void => (this.clock.setTime(checkTime(seconds)), this.loop.requestRender());
  play = (): void => this.setPlaying(true);
  /** Pauses, then advances one frame of 1/60 s at the time scale and draws it: the frame a 60 fps loop would draw next. */
  step = (): void => {
    this.setPlaying(false);
    this.clock.step(Number(this.params.timeScale));
    this.loop.requestRender();
  };
  pause = (): void => this.setPlaying(false);
  setCamera = (pose: CameraPose): void => this.orbit.setPose(checkCameraPose(pose));
  camera = (): CameraPose => this.orbit.pose();
  boat = (): BoatInfo => this.boatMotion.info();
  /** A link that reopens this exact view: parameters, camera, language, the current time (frozen) and the boat's motion. */
  shareUrl = (): string =>
    shareUrl(this.options, {
      params: this.params,
      time: this.clock.time,
      camera: this.camera(),
      boatState: this.boatMotion.snapshot(this.clock.time),
      wakeTrack: this.boatMotion.wakeText(this.clock.time),
      lesson: this.lesson(),
      probe: this.seaTools?.probeText(),
      stones: this.view.ocean.interactiveWaves?.stones(this.clock.time),
    });
  share = (): Promise<string> => shareLink(this.shareUrl(), this.notify);
  sampleSurface = (x: number, z: number, t = this.clock.time): SurfaceSample => (
    checkSurfacePoint(x, z),
    this.view.ocean.withInteractiveWaves(
      this.boatMotion.withWake(this.view.waves.sample(x, z, t), x, z, t, this.params, this.view.ocean.wakeWeight(x, z)),
      x,
      z,
    )
  );
  /** The still water's depth at world (x, z), metres (≤ 0 on land); on a coast, once its code has arrived (`ready` waits for it). */
  depth = (x: number, z: number): number => {
    checkSurfacePoint(x, z);
    const coast = this.view.ocean.coast;
    if (coast?.active) return coast.depth(x, z);
    if (this.params.bathymetry === 'deep') return this.params.depth;
    throw new Error("oceano.depth: the coast's code is still on its way; await oceano.ready or oceano.loaded() first.");
  };
  probeGpu = (points: unknown, time?: number): Promise<ProbeSample[]> =>
    this.view.probeSurface(checkProbe(points, time), time ?? this.clock.time);
  /** The sea tools' code, fetched the first time they are opened, a ?probe= link is followed or oceano.probe() is called. */
  loadSeaTools = (): Promise<SeaTools> =>
    (this.seaToolsLoad ??= import('./tools/seaTools').then((code) => (this.seaTools = new code.SeaTools(this))));

  /** A stone into the interactive waves; what is wrong with it, or raised, is said in a notice too (and bad arguments still throw). */
  disturb = (x: number, z: number, options: { radius?: number; height?: number } = {}): string[] => {
    let notices: Message[];
    try {
      notices = this.view.ocean.disturb(x, z, options);
    } catch (error) {
      if (error instanceof MessageError) this.notify(error.notice);
      throw error;
    }
    for (const notice of notices) this.notify(notice);
    this.loop.requestRender();
    return notices.map((notice) => this.tr.message(notice));
  };
  stats = (): OceanStats => this.frameStats.summary(this.view.stats(), this.view.waves.twinStatus?.() ?? null);
  /** The renderer side, for the API's debug calls (tables, pass timings, LOD timing, three's objects), and the physics panel. */
  debugView = (): OceanView => this.view;
  physicsPanel = () => this.controls?.physics();

  /** Frees every GPU resource and gives the WebGL context back to the browser (which allows only a few at once). */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.loop.dispose();
    this.resizeObserver?.disconnect();
    this.container.removeEventListener(FREE_AREA_EVENT, this.onFreeArea);
    this.context?.dispose();
    this.controls?.dispose();
    this.lessons?.dispose();
    this.seaTools?.dispose();
    if (this.started) {
      this.orbit.dispose();
      this.view.dispose();
      this.view.renderer.forceContextLoss();
    }
    disposeScaffold(this.scaffold);
  }
}
