import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { Vector3, type CubeTexture } from 'three';
import { validateParams, type OceanParams } from '../sim/params';
import { message, type Message } from '../sim/message';
import { OceanSurface, type SurfaceSample } from '../sim/oceanSurface';
import { median } from '../sim/sampleStatistics';
import { surfaceHeight } from '../sim/surface';
import { BoatMotion, type BoatMotionState } from '../sim/boatMotion';
import type { HullSize } from '../sim/boatPose';
import { OceanView } from '../render/oceanView';
import { BoatView } from '../render/boatView';
import { loadBoatModel } from '../render/boatModel';
import type { PassTiming } from '../render/underwaterPost';
import type { Submersion } from '../sim/underwater';
import { loadSkyCube } from '../render/skyCube';
import { isCameraPose, type CameraPose } from './cameraPose';
import { ControlPanel } from './controlPanel';
import { Translator, type Language } from './i18n';
import { BoatSteering } from './boatSteering';
import { Notices } from './notices';
import { FresnelPlot } from './fresnelPlot';
import { PlayButton } from './playButton';
import { SimulationClock } from './simulationClock';
import { formatUrlState, type UrlState } from './urlState';

export type { CameraPose } from './cameraPose';

/** How often a frame is followed by a GPU sync to measure its full cost (frames). */
const SYNC_EVERY = 8;
const FRAME_SAMPLES = 30;
/** The shipped model, relative to the page (or to oceano.js for the web component). */
export const DEFAULT_BOAT_MODEL = 'models/boat.glb';
/** Hull used to float the boat until (or unless) its model gives the real size: the shipped model's. */
const NOMINAL_HULL: HullSize = { length: 8, beam: 2.6 };
const DEG = Math.PI / 180;
/** How often the GUI's live LOD counts are refreshed (frames). */
const COUNTS_EVERY = 10;

export interface OceanStats {
  /** Median wall time of recent GPU-synced frames, update and draw together (ms). */
  frameMs: number;
  /** Median JavaScript time of recent frames' update step, before any draw call (ms). */
  cpuMs: number;
  /** Median CPU time of the boat's share of the update step (five surface samples, damping, pose), ms. */
  boatMs: number;
  drawCalls: number;
  triangles: number;
  /** The camera is below the surface at its own (x, z), by the CPU twin of the waves. */
  underwater: boolean;
  /** 'straddling': the waterline may cross the frame and is decided per pixel. */
  submersion: Submersion;
  /** EffectComposer passes run for the last frame; 0 above the water. */
  composerPasses: number;
  chunksTotal: number;
  chunksVisible: number;
  /** Cells of the far rings past the 4 km grid in view (src/sim/farRings.ts). */
  farCellsVisible: number;
  /** Visible chunks per LOD band, nearest band first. */
  lodCounts: number[];
  /** Time to first frame: navigation start to the first frame drawn and synced (ms); null before it. */
  ttffMs: number | null;
}

/** Why the frame loop is stopped although the app is alive. */
export type SuspendReason = 'hidden' | 'offscreen';

/**
 * Everything the app is told by its bootstrap (the page's main.ts or the <oceano-view>
 * element): the app itself reads no URL, attribute or media query.
 */
export interface OceanAppOptions {
  /** Validated settings from the URL or the element's attributes. */
  state: UrlState;
  language: Language;
  /** prefers-reduced-motion: start paused, with the play button showing. */
  reducedMotion: boolean;
  /** Directory holding the six sky images, as a URL or a path relative to the document. */
  skyBase: string;
  /** The boat's glTF, as a URL or a path relative to the document. */
  boatUrl: string;
  /** The link a shared view starts with (page address without its query). */
  shareBase: string;
  /** The lil-gui panel; off when embedded. */
  showPanel: boolean;
}

export interface LoopActivity {
  looping: boolean;
  framesDrawn: number;
}

export interface BoatInfo {
  /** Centre of the hull at the waterline, metres. */
  position: [number, number, number];
  /** Radians; the conventions of src/sim/boatPose.ts: heading clockwise from −z, pitch > 0 bow up, roll > 0 starboard up. */
  heading: number;
  pitch: number;
  roll: number;
  /** The undamped pose on the surface at this instant (equal to the above when the clock stands still). */
  target: { position: [number, number, number]; pitch: number; roll: number };
  model: 'loading' | 'loaded' | 'failed';
}

/** The default view, and the one "Surface" returns to. */
const DEFAULT_POSE: CameraPose = { position: [0, 9, 40], target: [0, 0, -60] };
/** Where "Dive" puts the eye, metres below the mean sea level, and how far ahead it looks. */
const DIVE_DEPTH = 6;
const DIVE_LOOK_AHEAD = 60;

/**
 * One live ocean in a container element: owns its canvas, the clock, the parameters, the
 * view and the controls, and runs the frame loop. The automation API is a thin layer over
 * its public methods. Several can live on one page.
 */
export class OceanApp {
  readonly notices: Notices;
  readonly clock: SimulationClock;
  readonly canvas: HTMLCanvasElement;
  readonly tr: Translator;
  private params: OceanParams;
  private surface: OceanSurface;
  private view!: OceanView;
  private controls!: OrbitControls;
  private panel?: ControlPanel;
  private fresnelPlot?: FresnelPlot;
  private readonly playButton: PlayButton;
  private resizeObserver?: ResizeObserver;
  private frameTimes: number[] = [];
  private updateTimes: number[] = [];
  private firstFrameAt: number | null = null;
  private boatTimes: number[] = [];
  private readonly boatMotion = new BoatMotion();
  private boatView!: BoatView;
  private boatState!: BoatMotionState;
  private hull: HullSize = NOMINAL_HULL;
  private boatModel: BoatInfo['model'] = 'loading';
  private steering?: BoatSteering;
  private frameCount = 0;
  private lastFrameTime: number | null = null;
  private animationHandle = 0;
  private pendingRender = 0;
  private looping = false;
  private started = false;
  private disposed = false;
  private contextLost = false;
  private contextLostNotice: HTMLElement | null = null;
  private readonly suspended = new Set<SuspendReason>();

  constructor(
    private readonly container: HTMLElement,
    private readonly options: OceanAppOptions,
  ) {
    const { state } = options;
    this.tr = new Translator(options.language);
    this.canvas = document.createElement('canvas');
    this.canvas.className = 'oceano-canvas';
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', this.tr.ui('canvasLabel'));
    container.appendChild(this.canvas);
    this.notices = new Notices(container, this.tr.ui('dismiss'));
    for (const notice of state.notices) this.notify(notice);
    this.params = { ...state.params };
    const running = state.time === null && !options.reducedMotion;
    this.clock = new SimulationClock(state.time ?? 0, running);
    this.surface = new OceanSurface(this.params);
    this.playButton = new PlayButton(container, { play: this.tr.ui('play'), pause: this.tr.ui('pause') }, () =>
      this.clock.playing ? this.pause() : this.play(),
    );
    this.playButton.sync(this.clock.playing);
  }

  /** Shows a message in the app's language. */
  notify(m: Message, level: 'warning' | 'error' = 'warning'): HTMLElement {
    return this.notices.show(this.tr.message(m), level);
  }

  /**
   * Builds the scene, draws the first frame and starts the loop; then loads the boat while
   * the sea runs, and resolves once a frame with the boat in it (or a notice saying why it
   * is missing) is on screen, so screenshots taken after `oceano.ready` always hold it.
   */
  async start(): Promise<void> {
    const sky = await this.loadSky();
    if (this.disposed) {
      sky?.dispose();
      return;
    }
    this.view = new OceanView(this.canvas, this.surface, sky, this.params);
    this.boatView = new BoatView(this.view.scene);
    this.controls = new OrbitControls(this.view.camera, this.canvas);
    this.controls.target.set(0, 0, -60);
    // The whole sphere around the target: orbiting below its level takes the eye under the water.
    this.controls.maxPolarAngle = Math.PI;
    this.controls.update();
    this.controls.addEventListener('change', this.requestRender);
    const { camera, cullingCamera } = this.options.state;
    if (cullingCamera && this.params.freezeCulling) {
      // Freeze the selection from the culling camera, then look at it from the preset's camera.
      this.setCamera(cullingCamera);
      this.view.update(this.clock.time);
    }
    if (camera) this.setCamera(camera);
    if (this.options.showPanel) {
      this.panel = new ControlPanel(
        this.container,
        this.params,
        this.clock.playing,
        {
          onParam: (key, value) => this.setParams({ [key]: value }),
          onPlayingChange: (playing) => (playing ? this.play() : this.pause()),
          onShare: () => void this.share(),
          onDive: () => this.dive(),
          onSurface: () => this.setCamera(DEFAULT_POSE),
        },
        this.tr,
      );
    }
    this.canvas.addEventListener('webglcontextlost', this.onContextLost);
    this.canvas.addEventListener('webglcontextrestored', this.onContextRestored);
    this.showFresnelPlot(this.params.fresnelPlot);
    // The full page steers from anywhere; an embedded figure only when it has the focus.
    const keyTarget: Window | HTMLElement = this.options.showPanel ? window : this.container;
    this.steering = new BoatSteering(keyTarget, (change) => this.setParams(change), () => this.params);
    this.resize();
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(this.canvas);
    this.started = true;
    this.renderFrame(true);
    // performance.now() counts from the navigation start, so this is the time to first frame.
    this.firstFrameAt = performance.now();
    this.updateLoop();
    await this.loadBoat();
    this.renderFrame(true);
  }

  private async loadBoat(): Promise<void> {
    const url = this.options.boatUrl;
    const indicator = document.createElement('div');
    indicator.className = 'oceano-loading';
    indicator.setAttribute('role', 'status');
    indicator.textContent = this.tr.ui('boatLoading');
    this.container.appendChild(indicator);
    try {
      const model = await loadBoatModel(url);
      this.hull = model.hull;
      this.view.lightWithCaustics(model.object);
      this.boatView.setModel(model.object);
      this.boatModel = 'loaded';
    } catch (error) {
      this.boatModel = 'failed';
      this.notify(message('boatLoadFailed', { reason: (error as Error).message }));
    } finally {
      indicator.remove();
    }
  }

  /** A page's own six images (`sky=`), or null for the sky painted from the sun. */
  private async loadSky(): Promise<CubeTexture | null> {
    const custom = this.options.state.sky;
    if (custom === null) return null;
    try {
      const sky = await loadSkyCube(this.options.skyBase);
      this.notify(message('skyCustomSunFixed', { base: custom }));
      return sky;
    } catch {
      this.notify(message('skyLoadFailed', { base: custom }));
      return null;
    }
  }

  private readonly loop = (now: number): void => {
    const seconds = this.lastFrameTime === null ? 0 : (now - this.lastFrameTime) / 1000;
    this.lastFrameTime = now;
    this.steering?.apply(Math.min(seconds, SimulationClock.MAX_STEP));
    this.clock.advance(seconds);
    this.renderFrame();
    this.animationHandle = requestAnimationFrame(this.loop);
  };

  /**
   * Runs the loop exactly when the app is started, playing, visible, on screen and has a GL
   * context. A paused view draws only when something changes (requestRender), so a page of
   * frozen figures costs nothing between interactions.
   */
  private updateLoop(): void {
    const shouldRun = this.started && !this.disposed && !this.contextLost && this.suspended.size === 0 && this.clock.playing;
    if (shouldRun === this.looping) return;
    this.looping = shouldRun;
    if (shouldRun) {
      // Time off screen is not simulated: the sea resumes where it stopped.
      this.lastFrameTime = null;
      this.animationHandle = requestAnimationFrame(this.loop);
    } else {
      cancelAnimationFrame(this.animationHandle);
    }
  }

  /** One frame on the next animation frame, for a paused view whose camera, size or parameters changed. */
  private readonly requestRender = (): void => {
    if (this.looping || this.pendingRender !== 0 || !this.started || this.disposed) return;
    this.pendingRender = requestAnimationFrame(() => {
      this.pendingRender = 0;
      this.renderFrame();
    });
  };

  /** Stops the frame loop while the tab is hidden or the view is scrolled away; a page of many views stays light. */
  setSuspended(reason: SuspendReason, suspended: boolean): void {
    if (suspended) this.suspended.add(reason);
    else this.suspended.delete(reason);
    this.updateLoop();
  }

  isStarted(): boolean {
    return this.started && !this.disposed;
  }

  activity(): LoopActivity {
    return { looping: this.looping, framesDrawn: this.frameCount };
  }

  private readonly onContextLost = (): void => {
    this.contextLost = true;
    this.updateLoop();
    this.contextLostNotice ??= this.notify(message('contextLost'), 'error');
  };

  /** three.js re-creates its GL state on restore and uploads every geometry, texture and program again on the next render. */
  private readonly onContextRestored = (): void => {
    this.contextLost = false;
    if (this.contextLostNotice) this.notices.remove(this.contextLostNotice);
    this.contextLostNotice = null;
    this.view.applyParams(this.params);
    this.resize();
    this.renderFrame();
    this.updateLoop();
  };

  /** Resizing clears the canvas, so a paused view draws again. */
  private resize(): void {
    const rect = this.canvas.getBoundingClientRect();
    this.view.setSize(rect.width, rect.height, Math.min(window.devicePixelRatio, 2));
    this.requestRender();
  }

  /**
   * Draws one frame at the clock's time. Every SYNC_EVERY frames, and whenever called
   * from outside the loop, a one-pixel read waits for the GPU so frameMs counts GPU work.
   */
  renderFrame(sync = this.frameCount % SYNC_EVERY === 0): void {
    if (this.contextLost) return;
    const start = performance.now();
    this.updateBoat();
    const boatEnd = performance.now();
    this.view.update(this.clock.time);
    const updateEnd = performance.now();
    this.boatTimes.push(boatEnd - start);
    this.updateTimes.push(updateEnd - start);
    if (this.boatTimes.length > FRAME_SAMPLES) this.boatTimes.shift();
    if (this.updateTimes.length > FRAME_SAMPLES) this.updateTimes.shift();
    this.view.draw();
    if (this.frameCount % COUNTS_EVERY === 0) this.panel?.showCounts(this.view.stats());
    this.frameCount++;
    if (!sync) return;
    const gl = this.view.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    this.frameTimes.push(performance.now() - start);
    if (this.frameTimes.length > FRAME_SAMPLES) this.frameTimes.shift();
  }

  /** The plot is made the first time it is asked for: most figures never show it. */
  private showFresnelPlot(visible: boolean): void {
    if (visible) this.fresnelPlot ??= new FresnelPlot(this.container, this.view.fresnelData);
    this.fresnelPlot?.setVisible(visible);
  }

  /** Floats the boat at the clock's time; with the camera following, carries the camera along. */
  private updateBoat(): void {
    const time = this.clock.time;
    const state = this.surface.stateAt(time);
    const maps = this.surface.heightmaps;
    const previous = this.boatState?.pose;
    this.boatState = this.boatMotion.update(
      time,
      { heading: this.params.boatHeading * DEG, speed: this.params.boatSpeed, response: this.params.boatResponse },
      this.hull,
      (x, z) => surfaceHeight(state, maps, x, z),
    );
    const pose = this.boatState.pose;
    this.boatView.setPose(pose);
    if (this.params.boatFollow && previous) this.moveCamera(pose.x - previous.x, pose.z - previous.z);
  }

  private moveCamera(dx: number, dz: number): void {
    if (dx === 0 && dz === 0) return;
    this.view.camera.position.x += dx;
    this.view.camera.position.z += dz;
    this.controls.target.x += dx;
    this.controls.target.z += dz;
    this.controls.update();
  }

  boat(): BoatInfo {
    const { pose, target } = this.boatState;
    return {
      position: [pose.x, pose.y, pose.z],
      heading: pose.heading,
      pitch: pose.pitch,
      roll: pose.roll,
      target: { position: [target.x, target.y, target.z], pitch: target.pitch, roll: target.roll },
      model: this.boatModel,
    };
  }

  getParams(): OceanParams {
    return { ...this.params };
  }

  /** Validates the whole update before applying any of it; throws a ParamError naming the bad key. */
  setParams(partial: unknown): OceanParams {
    const valid = validateParams(partial);
    const startsFollowing = valid.boatFollow === true && !this.params.boatFollow;
    this.params = { ...this.params, ...valid };
    // Following starts by looking at the boat from where the camera stands relative to its target.
    if (startsFollowing && this.boatState) {
      const { x, z } = this.boatState.pose;
      this.moveCamera(x - this.controls.target.x, z - this.controls.target.z);
    }
    this.view.applyParams(this.params);
    this.showFresnelPlot(this.params.fresnelPlot);
    this.panel?.sync(this.params, this.clock.playing);
    this.requestRender();
    return this.getParams();
  }

  setTime(seconds: number): void {
    if (typeof seconds !== 'number' || !Number.isFinite(seconds)) throw new TypeError(`setTime needs a finite number of seconds, got ${String(seconds)}.`);
    this.clock.setTime(seconds);
    this.requestRender();
  }

  play(): void {
    this.clock.playing = true;
    this.panel?.sync(this.params, true);
    this.playButton.sync(true);
    this.updateLoop();
  }

  pause(): void {
    this.clock.playing = false;
    this.panel?.sync(this.params, false);
    this.playButton.sync(false);
    this.updateLoop();
  }

  setCamera(pose: CameraPose): void {
    if (!isCameraPose(pose)) {
      throw new TypeError('setCamera needs { position: [x, y, z], target: [x, y, z] }: finite numbers within ±1e6 m, the target apart from the position.');
    }
    this.requestRender();
    const camera = this.view.camera;
    camera.position.fromArray(pose.position);
    this.controls.target.fromArray(pose.target);
    this.controls.update();
    // The controls rebuild target and position through a length clamp and spherical angles,
    // which moves them by an ulp or so; put back the exact ones (unless the controls clamped
    // the angle) so that a shared link reproduces the view bit for bit.
    if (camera.position.distanceTo(new Vector3().fromArray(pose.position)) < 1e-6) {
      this.controls.target.fromArray(pose.target);
      camera.position.fromArray(pose.position);
      camera.lookAt(this.controls.target);
    }
  }

  /** Puts the eye DIVE_DEPTH under the mean sea level where it is, looking level the way it looked. */
  dive(): void {
    const eye = this.view.camera.position;
    const heading = this.controls.target.clone().sub(eye).setY(0);
    if (heading.lengthSq() < 1e-12) heading.set(0, 0, -1);
    heading.normalize().multiplyScalar(DIVE_LOOK_AHEAD);
    this.setCamera({ position: [eye.x, -DIVE_DEPTH, eye.z], target: [eye.x + heading.x, -DIVE_DEPTH, eye.z + heading.z] });
  }

  camera(): CameraPose {
    return { position: this.view.camera.position.toArray(), target: this.controls.target.toArray() as [number, number, number] };
  }

  /** A link that reopens this exact view: parameters, camera, language and the current time (frozen). */
  shareUrl(): string {
    const { state } = this.options;
    const query = formatUrlState({
      params: this.params,
      time: this.clock.time,
      camera: this.camera(),
      language: this.options.language,
      sky: state.sky,
      boat: state.boat,
      embed: state.embed,
    });
    return `${this.options.shareBase}?${query}`;
  }

  /** Copies the share link; where the clipboard is refused, shows the link for the user to copy. */
  async share(): Promise<string> {
    const url = this.shareUrl();
    try {
      if (!navigator.clipboard) throw new Error('no clipboard');
      await navigator.clipboard.writeText(url);
      this.notify(message('shareCopied'));
    } catch {
      this.notify(message('shareFallback', { url }));
    }
    return url;
  }

  sampleSurface(x: number, z: number): SurfaceSample {
    if (!Number.isFinite(x) || !Number.isFinite(z)) throw new TypeError(`sampleSurface needs finite x and z, got ${String(x)}, ${String(z)}.`);
    return this.surface.sample(x, z, this.clock.time);
  }

  probeGpu(points: unknown, time?: number): SurfaceSample[] {
    const valid =
      Array.isArray(points) &&
      points.every((p) => Array.isArray(p) && p.length === 2 && p.every((c) => typeof c === 'number' && Number.isFinite(c)));
    if (!valid) throw new TypeError('probeGpu needs an array of [x, z] pairs of finite numbers.');
    if (time !== undefined && !Number.isFinite(time)) throw new TypeError(`probeGpu's time must be a finite number, got ${String(time)}.`);
    return this.view.probeSurface(points as [number, number][], time ?? this.clock.time);
  }

  stats(): OceanStats {
    return {
      frameMs: this.frameTimes.length ? median(this.frameTimes) : 0,
      cpuMs: this.updateTimes.length ? median(this.updateTimes) : 0,
      boatMs: this.boatTimes.length ? median(this.boatTimes) : 0,
      ...this.view.stats(),
      ttffMs: this.firstFrameAt,
    };
  }

  lodUpdateMs(batches?: number): number {
    if (batches !== undefined && !(Number.isInteger(batches) && batches >= 1 && batches <= 1000)) {
      throw new TypeError(`lodUpdateMs needs a whole number of batches between 1 and 1000, got ${String(batches)}.`);
    }
    return this.view.timeLodUpdate(batches);
  }

  /** One frame drawn with the GPU waited for after each pass: each pass's cost in ms. */
  passTimings(): PassTiming[] {
    return this.view.profileFrame(this.clock.time);
  }

  fresnelTable(): Float32Array {
    return this.view.fresnelData.slice();
  }

  fresnelTableFromBelow(): Float32Array {
    return this.view.fresnelFromBelowData.slice();
  }

  heightmaps(): { size: number; data: Float32Array }[] {
    return this.surface.heightmaps.map((map) => ({ size: map.size, data: map.data.slice() }));
  }

  three() {
    return { renderer: this.view.renderer, scene: this.view.scene, camera: this.view.camera };
  }

  /** Frees every GPU resource and gives the WebGL context back to the browser (which allows only a few at once). */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.updateLoop();
    cancelAnimationFrame(this.animationHandle);
    cancelAnimationFrame(this.pendingRender);
    this.resizeObserver?.disconnect();
    this.canvas.removeEventListener('webglcontextlost', this.onContextLost);
    this.canvas.removeEventListener('webglcontextrestored', this.onContextRestored);
    this.steering?.dispose();
    this.panel?.dispose();
    this.playButton.dispose();
    this.fresnelPlot?.dispose();
    this.notices.dispose();
    if (this.started) {
      this.controls.removeEventListener('change', this.requestRender);
      this.controls.dispose();
      this.view.dispose();
      this.view.renderer.forceContextLoss();
    }
    this.canvas.remove();
  }
}
