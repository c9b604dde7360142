import { PerspectiveCamera, Scene, WebGLRenderer, type CubeTexture, type Object3D } from 'three';
import { drawThroughHighlightRollOff } from '../tone/wholeFrameToneCurve';
import type { OceanParams, ParamKey } from '../../sim/params/params';
import { paramsChanged } from '../../sim/params/paramChanges';
import type { LiveWaveModel } from '../../sim/waves/waveModel';
import type { Submersion } from '../../sim/underwater/snellWindow';
import { sunDirection } from '../../sim/optics/sun';
import { DEFAULT_CAMERA } from '../../sim/camera/defaultCamera';
import type { WakeUniformData } from '../../sim/wake/wakeUniformData';
import { modelsDrawn, modelsMissing } from '../waves/waveViewRegistry';
import type { ProbeSample, SurfaceProbe } from '../teaching/surfaceProbe';
import type { TeachingFigure } from '../teaching/teachingFigure';
import type { Rect } from '../../sim/layout/rect';
import { SceneLights } from '../sky/sceneLights';
import type { KelvinGuideView } from '../wake/kelvinGuideView';
import type { CompareRenderer } from '../compare/compareRenderer';
import type { Strip } from '../../sim/compare/compareLayout';
import { compareModelNames } from '../../sim/compare/compareLayout';
import { UnderwaterStage } from '../underwater/underwaterStage';
import type { ChunkStats } from '../lod/oceanChunks';
import { DEFAULT_NEAR } from './nearPlane';
import { CAMERA_FAR, EyeClearance } from './eyeClearance';
import { LOOK_KEYS, OceanEngine } from './oceanEngine';

export interface RenderStats extends ChunkStats {
  drawCalls: number;
  triangles: number;
  /** The eye is below the surface at its own (x, z), by the CPU twin. */
  underwater: boolean;
  submersion: Submersion;
  /** EffectComposer passes run for the last frame: 0 when it was drawn directly. */
  composerPasses: number;
}

/**
 * The app's view, built on the library's Ocean: its own renderer, scene and camera, the
 * lights for the boat, the Kelvin guide, models side by side, the camera's planes fitted to
 * the water, the underwater passes and the teaching views. It is given its canvas,
 * parameters and the time of each frame; it reads no clock, URL or DOM of its own.
 */
export class OceanView {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera: PerspectiveCamera;
  readonly ocean: OceanEngine;
  /** compare=: the models side by side; its code is fetched the first time a comparison is asked for. */
  compare: CompareRenderer | null = null;
  /** Whether compare strips draw only the tiles that reach them (a diagnostic switches it off). */
  stripCulling = true;
  private compareCode?: typeof import('../compare/compareRenderer');
  private compareLoad?: Promise<void>;
  private disposed = false;
  readonly clearance = new EyeClearance();
  readonly underwater: UnderwaterStage;
  private readonly lights: SceneLights;
  /** The ±19.47° guide, its code fetched the first time it is shown. */
  private kelvinGuide?: KelvinGuideView;
  private kelvinGuideLoad?: Promise<void>;
  /** A page's own cube map, loaded by the app: the view disposes it. */
  private customSky: CubeTexture | null;
  private params: OceanParams;
  private applied: OceanParams | null = null;
  private showFigure = false;
  private figure?: TeachingFigure;
  private figureCode?: typeof import('../teaching/teachingFigure');
  private figureLoad?: Promise<void>;
  /** The canvas's CSS size, and the part of it the page's panels leave free (null: all of it). */
  private cssSize = { width: 1, height: 1 };
  private free: Rect | null = null;
  private probe?: SurfaceProbe;

  private lastStats: RenderStats = {
    drawCalls: 0,
    triangles: 0,
    chunksTotal: 0,
    chunksVisible: 0,
    farCellsVisible: 0,
    lodCounts: [],
    underwater: false,
    submersion: 'above',
    composerPasses: 0,
  };

  /**
   * `customSky`: a page's own cube map, or null for the sky painted from the sun. `redraw`
   * asks the app for a frame once a part loaded on first use (the underwater passes) has
   * arrived; `partFailed` says that part could not be fetched.
   */
  constructor(
    canvas: HTMLCanvasElement,
    customSky: CubeTexture | null,
    params: OceanParams,
    private readonly redraw: () => void = () => undefined,
    partFailed: () => void = () => undefined,
  ) {
    this.renderer = new WebGLRenderer({ canvas, antialias: false, powerPreference: 'high-performance', preserveDrawingBuffer: true });
    // Reset once per frame by draw(), so a frame of several composer passes counts them all.
    this.renderer.info.autoReset = false;
    drawThroughHighlightRollOff(this.renderer);
    this.camera = new PerspectiveCamera(55, 16 / 9, DEFAULT_NEAR, CAMERA_FAR);
    this.camera.position.fromArray(DEFAULT_CAMERA.position);
    this.camera.lookAt(...DEFAULT_CAMERA.target);
    this.customSky = customSky;
    this.params = params;
    this.ocean = new OceanEngine(this.renderer, params, customSky);
    this.scene.add(this.ocean.sky, this.ocean);
    this.lights = new SceneLights(this.scene);
    this.underwater = new UnderwaterStage(this.renderer, this.scene, this.camera, this.ocean, redraw, partFailed);
    this.applyParams(params);
  }

  /** The models on screen: `waves` and `compare` as last applied. */
  shownModels(): Pick<OceanParams, 'waves' | 'compare'> {
    return { waves: this.params.waves, compare: this.params.compare };
  }

  /** The CPU twin of the waves on screen: the boat, the underwater switch and the API sample it. */
  get waves(): LiveWaveModel {
    return this.ocean.waves;
  }

  /**
   * Applies the parameters that differ from the last ones applied. Keyboard steering changes
   * the boat every frame; that must not rebuild or re-upload anything the view already has.
   * The caller loads every drawn model's code first (OceanApp): the view never waits.
   */
  applyParams(params: OceanParams): void {
    const missing = modelsMissing(modelsDrawn(params));
    if (missing.length > 0) throw new Error(`Wave model code not loaded: ${missing.join(', ')}.`);
    const before = this.applied;
    const changed = (...keys: ParamKey[]) => paramsChanged(before, params, keys);
    const first = before === null;
    this.applied = { ...params };
    this.params = params;
    if (!first) this.ocean.apply(params);
    this.ensureCompare(params);
    this.compare?.apply(params);
    if (changed(...LOOK_KEYS)) this.compare?.applyLook(params);
    if (changed('sunElevation', 'sunAzimuth', 'waterColor'))
      this.lights.update(sunDirection(params.sunElevation, params.sunAzimuth), params.waterColor);
    if (changed('view')) this.showFigure = params.view !== 'ocean';
    if (changed('exposure')) this.renderer.toneMappingExposure = 2 ** params.exposure;
    // The teaching views' code is fetched the first time one is shown; until then the frame is clear.
    if (this.showFigure) {
      this.figureLoad ??= import('../teaching/teachingFigure').then(
        (code) => {
          this.figureCode = code;
          if (!this.disposed) this.redraw();
        },
        (error: unknown) => console.warn("Oceano: the teaching view's code could not be loaded.", error),
      );
    }
  }

  /** The boat's wake for the coming frame, its culling bound, and the ±19.47° teaching guide at the boat. */
  setWake(data: WakeUniformData, bound: number, guide: { visible: boolean; x: number; y: number; z: number; heading: number }): void {
    this.ocean.setWake(data, bound);
    if (guide.visible && !this.kelvinGuide) {
      this.kelvinGuideLoad ??= import('../wake/kelvinGuideView').then(
        ({ KelvinGuideView }) => {
          if (this.disposed) return;
          this.kelvinGuide = new KelvinGuideView(this.scene);
          this.redraw();
        },
        (error: unknown) => console.warn("Oceano: the Kelvin guide's code could not be loaded.", error),
      );
    }
    this.kelvinGuide?.update(guide.visible, guide.x, guide.y, guide.z, guide.heading);
  }

  /** Lets the sunlight on a model (the boat) pass through the waves: caustics on its wet side. */
  lightWithCaustics(model: Object3D): void {
    this.ocean.lightWithCaustics(model);
  }

  /** After a lost WebGL context comes back: paints again what lived only in render targets (the sun's sky). */
  contextRestored(): void {
    this.ocean.contextRestored();
    this.compare?.contextRestored();
  }

  /** Shows a page's own cube map from now on (the sun then moves only the lighting). */
  setSky(sky: CubeTexture): void {
    this.ocean.setSky(sky);
    this.compare?.setSky(sky);
    if (this.customSky !== sky) this.customSky?.dispose();
    this.customSky = sky;
  }

  setSize(width: number, height: number, pixelRatio: number): void {
    const w = Math.max(1, Math.floor(width));
    const h = Math.max(1, Math.floor(height));
    this.renderer.setPixelRatio(pixelRatio);
    this.renderer.setSize(w, h, false);
    this.cssSize = { width: w, height: h };
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.underwater.fitToCanvas();
  }

  /** The part of the canvas (CSS px) that the page's panels leave free: compare strips and teaching views are laid out in it. */
  setFreeArea(free: Rect | null): void {
    this.free = free;
  }

  /**
   * The CPU half of a frame: everything decided before drawing (the waves, the camera's
   * planes, which side of the water the eye is on, the chunks in view). Kept apart from
   * draw() so its cost can be measured alone.
   */
  update(time: number): void {
    const { ocean, camera } = this;
    ocean.follow(camera);
    ocean.advance(time);
    this.compare?.advance(time);
    this.clearance.fitNear(camera, ocean.cullingBounds().vertical, () => ocean.surfaceUnder(camera.position.x, camera.position.z, time));
    const place = ocean.locateEye(camera, time);
    this.clearance.fitFar(camera, place.submersion, this.params.fogDensity);
    const strips = this.splitStrips();
    if (strips && this.compare) this.compare.cull(strips, camera);
    else ocean.cull(camera);
    ocean.shade(camera);
  }

  /** Settles once every part asked for so far (the underwater passes, the compare code, the Kelvin guide, the ocean's own) has loaded. */
  whenPartsLoaded(): Promise<void> {
    return Promise.all([
      this.underwater.whenLoaded(),
      this.ocean.whenReady(),
      this.compareLoad,
      this.figureLoad,
      this.kelvinGuideLoad,
    ]).then(() => undefined);
  }

  /**
   * Makes the compare renderer once a comparison is asked for, fetching its code the first
   * time; until it has arrived the first model is drawn whole, and `redraw` is called then.
   */
  private ensureCompare(params: OceanParams): void {
    if (this.compare || compareModelNames(params.compare).length < 2) return;
    if (this.compareCode) {
      this.compare = new this.compareCode.CompareRenderer(this.renderer, this.scene, this.ocean);
      return;
    }
    this.compareLoad ??= import('../compare/compareRenderer').then(
      (code) => {
        this.compareCode = code;
        if (this.disposed) return;
        this.ensureCompare(this.params);
        this.compare?.apply(this.params);
        this.redraw();
      },
      (error: unknown) => console.warn("Oceano: the compare view's code could not be loaded; the first model is drawn alone.", error),
    );
  }

  /** Submits the frame prepared by update(): directly above water, through the underwater passes below it. */
  draw(): void {
    this.renderer.info.reset();
    const { underwater, submersion } = this.ocean.place;
    let composerPasses = 0;
    const strips = this.splitStrips();
    if (this.showFigure || submersion === 'above' || this.underwater.failed) this.underwater.resetEncoding();
    if (this.showFigure) this.drawFigure();
    else if (strips && this.compare) this.compare.draw(strips, this.camera);
    else if (submersion === 'above' || this.underwater.failed) this.renderer.render(this.scene, this.camera);
    else composerPasses = this.underwater.passes()?.render() ?? 0;
    const info = this.renderer.info.render;
    // Wireframe draws each ocean triangle as three line segments (three.js's wireframe index), counted as lines.
    const triangles = info.triangles + (this.ocean.material.wireframe ? Math.round(info.lines / 3) : 0);
    this.lastStats = { drawCalls: info.calls, triangles, ...this.ocean.chunks.stats(), underwater, submersion, composerPasses };
  }

  /** The strips of a split frame (compare= above the water, not a teaching view); null for a whole frame. */
  splitStrips(): Strip[] | null {
    if (this.showFigure || this.ocean.submersion !== 'above') return null;
    if (this.compare) this.compare.stripCulling = this.stripCulling;
    const { free, cssSize } = this;
    // The dividers stand in the free part of the canvas; the outer strips reach its edges.
    return this.compare?.strips(this.params, free ? [free.x / cssSize.width, (free.x + free.width) / cssSize.width] : [0, 1]) ?? null;
  }

  /** The teaching view; one with nothing to show (a model without heightmaps) leaves the screen clear. */
  private drawFigure(): void {
    const ocean = this.ocean;
    const canvas = this.cssSize;
    const drawn =
      this.figureCode &&
      (this.figure ??= new this.figureCode.TeachingFigure()).draw(this.renderer, {
        params: this.params,
        time: ocean.time,
        waves: ocean.waveModelView,
        sky: ocean.skyTexture,
        free: this.free ?? { x: 0, y: 0, ...canvas },
        canvas,
      });
    if (!drawn) this.renderer.clear();
  }

  /** Waits for every GPU command so far: reading one canvas pixel cannot finish before them. */
  waitForGpu(): void {
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  }

  /** The active model's GPU chunk evaluated at grid points (x, z) and a time; the probe's code is fetched on first use. */
  async probeSurface(points: readonly (readonly [number, number])[], time: number): Promise<ProbeSample[]> {
    const frameTime = this.ocean.time;
    const { SurfaceProbe } = await import('../teaching/surfaceProbe');
    this.probe ??= new SurfaceProbe(this.renderer, this.ocean.binding, this.ocean.wakeUniforms, this.ocean.interactiveWaveUniforms);
    this.probe.setInteractiveWavesOn(this.ocean.interactiveWaves !== null);
    this.probe.setCoast(this.ocean.coast?.active ? this.ocean.coast.uniforms : null);
    this.ocean.waveModelView.update(time);
    this.ocean.coast?.update(time);
    try {
      return this.probe.probe(points);
    } finally {
      this.ocean.waveModelView.update(frameTime);
      this.ocean.coast?.update(frameTime);
    }
  }

  stats(): RenderStats {
    return { ...this.lastStats, lodCounts: this.lastStats.lodCounts.slice() };
  }

  dispose(): void {
    this.ocean.dispose();
    this.disposed = true;
    this.compare?.dispose();
    this.probe?.dispose();
    this.figure?.dispose();
    this.underwater.dispose();
    this.kelvinGuide?.dispose();
    this.customSky?.dispose();
    this.renderer.dispose();
  }
}
