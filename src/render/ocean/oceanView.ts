import { Color, PerspectiveCamera, Scene, Vector2, Vector3, WebGLRenderer, type CubeTexture, type DataTexture, type IUniform, type Object3D } from 'three';
import type { OceanParams, ParamKey } from '../../sim/params/params';
import { paramsChanged } from '../../sim/params/paramChanges';
import { median } from '../../sim/physics/sampleStatistics';
import type { LiveWaveModel, WavesChoice } from '../../sim/waves/waveModel';
import { compareModelNames, compareStrips, type Strip } from '../../sim/compare/compareLayout';
import { AIR_IOR, fresnelReflectance, fresnelTable, WATER_IOR } from '../../sim/optics/fresnel';
import { SUN_LIGHT_COLOR, sunDirection } from '../../sim/optics/sun';
import { DEFAULT_CAMERA } from '../../sim/camera/defaultCamera';
import { classifyNearPlane, fresnelTableFromBelow, refractedSunDirection, type Submersion } from '../../sim/underwater/snellWindow';
import { createWaterVolumeUniforms, applyWaterVolume, setEyeDepth, type WaterVolumeUniforms } from '../underwater/waterVolumeUniforms';
import { applyCaustics, createCausticsUniforms, type CausticsUniforms } from '../underwater/causticsUniforms';
import { SeaBed } from '../underwater/seaBed';
import type { PassTiming, UnderwaterPost } from '../underwater/underwaterPost';
import { OceanMaterial } from './oceanMaterial';
import { OceanChunks, type ChunkStats, type LodSettings } from './oceanChunks';
import { fresnelTexture } from '../optics/dataTextures';
import type { ProbeSample, SurfaceProbe } from '../teaching/surfaceProbe';
import { HeightmapView } from '../teaching/heightmapView';
import { SceneLights } from '../sky/sceneLights';
import { lightWithCaustics } from '../underwater/hullCaustics';
import { WaveBinding } from '../waves/waveBinding';
import { createWaveModelView, modelsDrawn, modelsMissing } from '../waves/waveViewRegistry';
import type { WaveModelView } from '../waves/waveModelView';
import { SunSky } from '../sky/sunSky';
import { SkyBackground } from '../sky/skyBackground';
import { CompareSide, type OceanMaterialInputs } from '../compare/compareSide';
import { applyWakeUniforms, createWakeUniforms } from '../wake/wakeUniforms';
import { KelvinGuideView } from '../wake/kelvinGuideView';
import type { WakeUniformData } from '../../sim/wake/wakeUniformData';
import { DEFAULT_NEAR, nearForClearance } from './nearPlane';
import { fogHidingDistance } from '../../sim/underwater/waterFog';
import { SurfaceHeightMemo } from '../../sim/waves/surfaceHeightMemo';
import { encodeSceneForPost } from '../underwater/sceneEncoding';

/**
 * How far from the surface a near-plane sample must be to decide the whole near plane,
 * metres: it covers the surface rising or dipping between the 3 × 3 samples (spaced about
 * half a metre) on the steepest ripples.
 */
const WATERLINE_MARGIN = 0.25;
/**
 * Past the far rings' skirt (src/sim/lod/farRings.ts), so the sea meets the horizon from 10 km
 * up. Depth precision is set by the near plane, not this (with far ≫ near).
 */
const CAMERA_FAR = 1e9;
const NEAR_PLANE_SAMPLES: readonly [number, number][] = [-1, 0, 1].flatMap((x) => [-1, 0, 1].map((y) => [x, y] as [number, number]));

/** The fixes for far views, each on unless a negative control turns it off. */
export interface ShadingFixes {
  /** Per-pixel detail normals in the far bands (shaders/ocean.frag, WAVE_DETAIL_NORMALS). */
  detailNormals: boolean;
  /** Positions relative to a render origin near the camera on the GPU (OceanMaterial.onBeforeRender). */
  cameraRelative: boolean;
  /** The sea bed marks itself as under the water for the waterline test (shaders/waterline.glsl). */
  seaBedMark: boolean;
  /** Gerstner's and FFT's per-pixel normals and foam at grid points relative to the render origin (ocean.frag). */
  relativePixelNormals: boolean;
  /** The near plane brought in for an eye less than about a metre above the water (src/render/ocean/nearPlane.ts). */
  clearanceNear: boolean;
  /**
   * Whole view under the water: the sea drawn from below only (back faces, the shading from
   * above compiled out: OceanMaterial.setSeenFromBelow) and the sea bed's caustics without
   * their above-the-surface test when the bed lies below every trough (SeaBed.setDepth), and
   * the far plane at the distance the fog hides (OceanView.fitFarPlane). Off, both faces and
   * both shadings are drawn, the test runs and the far plane stays out, as before (issue 14).
   */
  underwaterShortcuts: boolean;
}

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
 * The three.js side of the ocean: renderer, scene, camera, the chunked ocean, the sea bed
 * and the underwater passes. It is given its canvas, its surface data and the time of each
 * frame; it reads no clock, URL or DOM of its own.
 */
export class OceanView {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera: PerspectiveCamera;
  readonly fresnelData = fresnelTable(256);
  readonly fresnelFromBelowData = fresnelTableFromBelow(256);
  private readonly material: OceanMaterial;
  private readonly ocean: OceanChunks;
  private lod: LodSettings;
  /** The active wave model's GPU half; its `model` is the CPU twin everything else samples. */
  private waveView: WaveModelView;
  private readonly waveBinding: WaveBinding;
  private bounds: { vertical: number; horizontal: number };
  /** The time of the last update(), to put the wave uniforms back after a probe at another time. */
  private frameTime = 0;
  private readonly fresnelTexture: DataTexture;
  private readonly fresnelFromBelowTexture: DataTexture;
  private readonly waterVolume: WaterVolumeUniforms = createWaterVolumeUniforms();
  private readonly caustics: CausticsUniforms = createCausticsUniforms();
  /** The boat's wake (shaders/wake.glsl), shared by the ocean and the probe; filled by setWake. */
  private readonly wake = createWakeUniforms();
  /** How far the wake can raise or lower the surface this frame (wakeHeightBound), metres. */
  private wakeBound = 0;
  private appliedWake: WakeUniformData | null = null;
  private readonly kelvinGuide: KelvinGuideView;
  private readonly light: Record<'uRefractedSun' | 'uSunColor', IUniform> = {
    uRefractedSun: { value: new Vector3() },
    uSunColor: { value: new Color(...SUN_LIGHT_COLOR) },
  };
  private readonly seaBed: SeaBed;
  private readonly lights: SceneLights;
  /** Made on the first frame that needs it, so a view that never dives never pays for its targets. */
  private post?: UnderwaterPost;
  private underwaterCode?: typeof import('../underwater/underwaterPost');
  private underwaterLoad?: Promise<void>;
  /** The underwater passes' code could not be fetched: frames below the surface are drawn without them. */
  private underwaterFailed = false;
  private shaftLightWindowForced = false;
  private params: OceanParams;
  /** The parameters as last applied, to apply only what changes; null before the first time. */
  private applied: OceanParams | null = null;
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
  private where: { underwater: boolean; submersion: Submersion } = { underwater: false, submersion: 'above' };
  private probe?: SurfaceProbe;
  private heightmapView?: HeightmapView;
  private showHeightmaps = false;
  private readonly nearPoint = new Vector3();
  /** The surface's height under the eye (asked by the near plane's fit and the submersion test). */
  private readonly eyeSurface = new SurfaceHeightMemo();
  /** Debug (a negative control): false keeps the fixed 0.5 m near plane however low the eye. */
  private clearanceNear = true;
  /** Debug (a negative control's switch): see ShadingFixes.underwaterShortcuts. */
  private underwaterShortcuts = true;
  private readonly axis = new Vector3();
  private readonly skyBackground: SkyBackground;
  private readonly syncPixel = new Uint8Array(4);
  /** The sky painted from the sun; absent while a page's own six images are shown. */
  private sunSky: SunSky | null = null;
  private sky: CubeTexture;
  /** What a compare side's ocean material shares with the view's own. */
  private readonly materialInputs: OceanMaterialInputs;
  /** compare=a,b[,c]: the models after the first (which is this view's own), left to right. */
  private sides: CompareSide[] = [];
  private readonly bufferSize = new Vector2();
  /** A strip's culling camera (see stripCamera). */
  private readonly cullCamera = new PerspectiveCamera();
  /**
   * Debug (oceano.debug.stripCulling): whether a compare strip draws a chunk straddling it as
   * the tiles that reach it (OceanChunks, TILES). Off, each strip draws its chunks whole.
   */
  stripCulling = true;

  /**
   * `sky`: a page's own cube map (whose sun stays where it was painted), or null for the
   * default sky, painted from the sun parameters and repainted whenever they change.
   * `redraw`: asks the app for a frame, once a part loaded on first use (the underwater
   * passes) has arrived. `partFailed`: that part could not be fetched (the view then draws
   * without it).
   */
  constructor(
    canvas: HTMLCanvasElement,
    customSky: CubeTexture | null,
    params: OceanParams,
    private readonly redraw: () => void = () => undefined,
    private readonly partFailed: () => void = () => undefined,
  ) {
    this.renderer = new WebGLRenderer({ canvas, antialias: false, powerPreference: 'high-performance', preserveDrawingBuffer: true });
    // Reset once per frame by draw(), so a frame of several composer passes counts them all.
    this.renderer.info.autoReset = false;
    this.camera = new PerspectiveCamera(55, 16 / 9, DEFAULT_NEAR, CAMERA_FAR);
    this.camera.position.fromArray(DEFAULT_CAMERA.position);
    this.camera.lookAt(...DEFAULT_CAMERA.target);

    performance.mark('oceano:renderer');
    if (!customSky) this.sunSky = new SunSky();
    performance.mark('oceano:sky-clouds');
    const sky = customSky ?? (this.sunSky as SunSky).texture;
    this.sky = sky;
    this.skyBackground = new SkyBackground(sky);
    this.scene.add(this.skyBackground.mesh);
    this.waveView = createWaveModelView({ ...params, waves: firstModel(params) }, this.renderer);
    this.waveBinding = new WaveBinding(this.waveView);
    performance.mark('oceano:wave-model');
    this.fresnelTexture = fresnelTexture(this.fresnelData);
    this.fresnelFromBelowTexture = fresnelTexture(this.fresnelFromBelowData);
    this.materialInputs = {
      fresnelTables: { fromAbove: this.fresnelTexture, fromBelow: this.fresnelFromBelowTexture },
      sky,
      shared: { ...this.waterVolume, ...this.wake, uSunColor: this.light.uSunColor },
    };
    this.material = new OceanMaterial(this.waveBinding, this.materialInputs.fresnelTables, sky, this.materialInputs.shared);
    this.ocean = new OceanChunks(this.material);
    this.scene.add(this.ocean.group);
    this.lod = params;
    this.bounds = this.waveView.model.bounds();
    this.seaBed = new SeaBed(this.waveBinding, { ...this.waterVolume, ...this.caustics, ...this.light });
    this.scene.add(this.seaBed.mesh);
    this.lights = new SceneLights(this.scene);
    this.kelvinGuide = new KelvinGuideView(this.scene);
    this.params = params;
    performance.mark('oceano:scene');
    this.applyParams(params);
    performance.mark('oceano:sky-painted');
  }

  /** The models on screen: `waves` and `compare` as last applied. */
  shownModels(): Pick<OceanParams, 'waves' | 'compare'> {
    return { waves: this.params.waves, compare: this.params.compare };
  }

  /** The CPU twin of the waves on screen: the boat, the underwater switch and the API sample it. */
  get waves(): LiveWaveModel {
    return this.waveView.model;
  }

  /**
   * Applies the parameters that differ from the last ones applied (all of them the first
   * time). Keyboard steering changes the boat's speed and heading every frame; that must
   * not rebuild blur kernels or re-upload anything the view already has.
   */
  applyParams(params: OceanParams): void {
    // The caller loads every drawn model's code first (OceanApp, loadWaveModels): the view never waits.
    const missing = modelsMissing(modelsDrawn(params));
    if (missing.length > 0) throw new Error(`Wave model code not loaded: ${missing.join(', ')}.`);
    const before = this.applied;
    const changed = (...keys: ParamKey[]) => paramsChanged(before, params, keys);
    this.applied = { ...params };
    this.params = params;
    const first = firstModel(params);
    if (first !== this.waveView.name) {
      const previous = this.waveView;
      this.waveView = createWaveModelView({ ...params, waves: first }, this.renderer);
      this.waveBinding.setModel(this.waveView);
      previous.dispose();
    }
    const newSides = this.syncCompareSides(compareModelNames<WavesChoice>(params.compare).slice(1), params);
    // Every model, a new one too: each compares what it reads and re-uploads only on a change
    // (and a new view gets what it does not take from its model, such as the FFT's foam).
    this.waveView.setParams(params);
    for (const side of this.sides) side.view.setParams(params);
    for (const side of newSides) applyLook(side.material, params);
    // Chunk boxes reach as far as any wave can move a vertex, so a crest rising into view is never culled.
    this.bounds = this.waveView.model.bounds();
    if (changed('seed')) this.seaBed.setNoiseSeed(params.seed);
    if (changed('sunElevation', 'sunAzimuth', 'waterColor', 'fogDensity', 'caustics', 'causticsIntensity')) {
      const sun = sunDirection(params.sunElevation, params.sunAzimuth);
      this.sunSky?.update(this.renderer, sun);
      this.lights.update(sun, params.waterColor);
      const refracted = refractedSunDirection(sun);
      (this.light.uRefractedSun.value as Vector3).fromArray(refracted ?? [0, 0, 0]);
      applyWaterVolume(this.waterVolume, params.waterColor, sun[1], params.fogDensity);
      applyCaustics(this.caustics, sun, params.caustics, params.causticsIntensity);
      this.seaBed.setSunTransmission(1 - fresnelReflectance(Math.max(0, sun[1]), AIR_IOR, WATER_IOR));
    }
    if (changed(...LOOK_KEYS)) for (const material of [this.material, ...this.sides.map((s) => s.material)]) applyLook(material, params);
    if (changed('view')) this.showHeightmaps = params.view === 'heightmap';
    if (changed('lodDistance', 'lodBands', 'lodBruteForce', 'freezeCulling', 'lodMorph')) {
      this.lod = { lodDistance: params.lodDistance, lodBands: params.lodBands, lodBruteForce: params.lodBruteForce, freezeCulling: params.freezeCulling, lodMorph: params.lodMorph };
    }
    // The wave bound too: a bed below every trough skips the caustics' above-the-surface test.
    this.seaBed.setDepth(params.seaBedDepth, this.underwaterShortcuts ? this.bounds.vertical : Infinity);
    if (changed('blurStrength')) this.post?.setBlur(params.blurStrength);
    if (changed('godRays', 'godRaysIntensity')) this.post?.setGodRays(params.godRays ? params.godRaysIntensity : 0);
  }

  /**
   * Keeps one CompareSide per model after the first, in order, reusing those already made;
   * returns the new ones (whose materials still need the look applied).
   */
  private syncCompareSides(names: readonly WavesChoice[], params: OceanParams): CompareSide[] {
    const kept: CompareSide[] = [];
    const made: CompareSide[] = [];
    const unused = [...this.sides];
    for (const name of names) {
      const k = unused.findIndex((side) => side.name === name);
      if (k >= 0) {
        kept.push(unused.splice(k, 1)[0]);
      } else {
        const side = new CompareSide(name, params, this.renderer, this.materialInputs);
        this.scene.add(side.chunks.group);
        kept.push(side);
        made.push(side);
      }
    }
    for (const side of unused) side.dispose();
    this.sides = kept;
    return made;
  }

  /**
   * The boat's wake for the coming frame: its uniforms (packed by src/sim/wake/boatWake.ts), the
   * bound that grows the culling boxes, and the ±19.47° teaching guide at the boat.
   */
  setWake(data: WakeUniformData, bound: number, guide: { visible: boolean; x: number; y: number; z: number; heading: number }): void {
    // The same packed data as last frame (a paused view, or the wake off) is already uploaded.
    if (data !== this.appliedWake) applyWakeUniforms(this.wake, data);
    this.appliedWake = data;
    this.material.setWakeOn(data.count >= 2);
    this.wakeBound = bound;
    this.kelvinGuide.update(guide.visible, guide.x, guide.y, guide.z, guide.heading);
  }

  /** The culling bounds: the model's, grown by the wake's. */
  private cullingBounds(): { vertical: number; horizontal: number } {
    return this.wakeBound === 0 ? this.bounds : { vertical: this.bounds.vertical + this.wakeBound, horizontal: this.bounds.horizontal };
  }

  /** Lets the sunlight on a model (the boat) pass through the waves: caustics on its wet side. */
  lightWithCaustics(model: Object3D): void {
    lightWithCaustics(model, this.waveBinding, this.caustics);
  }

  /** After a lost WebGL context comes back: draws again what lived only in render targets (the FFT's fields, the sun's sky). */
  contextRestored(): void {
    this.ocean.forgetSelection();
    for (const view of [this.waveView, ...this.sides.map((side) => side.view)]) view.contextRestored?.();
    if (!this.sunSky) return;
    this.sunSky.forget();
    this.sunSky.update(this.renderer, sunDirection(this.params.sunElevation, this.params.sunAzimuth));
  }

  /** Shows a page's own cube map from now on (the sun then moves only the lighting). */
  setSky(sky: CubeTexture): void {
    if (this.sunSky) this.sunSky.dispose();
    else this.sky.dispose();
    this.sunSky = null;
    this.sky = sky;
    this.skyBackground.setSky(sky);
    this.materialInputs.sky = sky;
    this.material.setSky(sky);
    for (const side of this.sides) side.material.setSky(sky);
  }

  setSize(width: number, height: number, pixelRatio: number): void {
    const w = Math.max(1, Math.floor(width));
    const h = Math.max(1, Math.floor(height));
    this.renderer.setPixelRatio(pixelRatio);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.post?.setSize(w, h, pixelRatio);
  }

  /**
   * Brings the near plane in for an eye less than about a metre above the surface under it,
   * so that it stays above the water and the lower frame shows the surface from above
   * (src/render/ocean/nearPlane.ts); 0.5 m otherwise. The projection is remade only on a change, so
   * a view that keeps its near plane keeps its culling capture.
   */
  private fitNearPlane(time: number): void {
    const camera = this.camera;
    let near = DEFAULT_NEAR;
    // An eye this high over the highest crest keeps 0.5 m whichever way it looks
    // (nearPlane.ts needs at most 3.7 m of clearance per metre of near distance).
    if (this.clearanceNear && camera.position.y < this.bounds.vertical + 2) {
      const clearance = camera.position.y - this.eyeSurface.height(this.waveView.model, camera.position.x, camera.position.z, time);
      camera.updateMatrixWorld();
      const e = camera.matrixWorld.elements;
      near = nearForClearance(clearance, {
        forwardY: -e[9] / this.axis.set(e[8], e[9], e[10]).length(),
        upY: e[5] / this.axis.set(e[4], e[5], e[6]).length(),
        rightY: e[1] / this.axis.set(e[0], e[1], e[2]).length(),
        tanHalfFov: Math.tan((camera.fov * Math.PI) / 360),
        aspect: camera.aspect,
      });
    }
    if (near !== camera.near) {
      camera.near = near;
      camera.updateProjectionMatrix();
    }
  }

  /**
   * Wholly under the water, the far plane comes in to where the fog hides everything
   * (src/sim/underwater/waterFog.ts: 396 m at the default density): the chunks beyond are culled and
   * their pixels, left empty, get the water's colour from the underwater pass, as a surface
   * that far would (within half an output level). Looking up from below, the surface's far
   * bands out to the horizon were most of the frame's vertex work.
   */
  private fitFarPlane(): void {
    const below = this.where.submersion === 'below' && this.underwaterShortcuts;
    const far = below ? Math.min(CAMERA_FAR, fogHidingDistance(this.waterVolume.uFogDensity.value)) : CAMERA_FAR;
    if (far !== this.camera.far) {
      this.camera.far = far;
      this.camera.updateProjectionMatrix();
    }
  }

  /**
   * Where the view starts: 'above' and 'below' when the eye and the whole near plane are
   * clear of the surface on one side, else 'straddling' (the waterline may cross the frame).
   */
  private submersionAt(time: number): { underwater: boolean; submersion: Submersion; eyeSurface: number } {
    const waves = this.waveView.model;
    const eye = this.camera.position;
    const eyeSurface = this.eyeSurface.height(waves, eye.x, eye.z, time);
    const underwater = eye.y < eyeSurface;
    // The near plane lies within `reach` of the eye: far above the highest crest, no sampling needed.
    const nearHalfHeight = this.camera.near * Math.tan((this.camera.fov * Math.PI) / 360);
    const reach = Math.hypot(this.camera.near, nearHalfHeight, nearHalfHeight * this.camera.aspect);
    // The samples are spaced in proportion to the near distance, and so is what the surface
    // can do between them: 0.25 m at the default 0.5 m.
    const margin = WATERLINE_MARGIN * (this.camera.near / DEFAULT_NEAR);
    if (eye.y - reach > this.bounds.vertical + margin) return { underwater, submersion: 'above', eyeSurface };
    this.camera.updateMatrixWorld();
    const points = [{ y: eye.y, surface: eyeSurface }];
    for (const [x, y] of NEAR_PLANE_SAMPLES) {
      const p = this.nearPoint.set(x, y, -1).unproject(this.camera);
      points.push({ y: p.y, surface: waves.height(p.x, p.z, time) });
    }
    return { underwater, submersion: classifyNearPlane(points, margin), eyeSurface };
  }

  /**
   * The CPU half of a frame: everything that must be decided before drawing (surface
   * uniforms, chunk selection, which side of the water the eye is on). Kept apart from
   * draw() so its cost can be measured alone.
   */
  update(time: number): void {
    this.frameTime = time;
    this.waveView.update(time);
    for (const side of this.sides) side.view.update(time);
    this.fitNearPlane(time);
    const { eyeSurface, ...where } = this.submersionAt(time);
    this.where = where;
    this.fitFarPlane();
    const strips = this.splitStrips();
    if (!strips) {
      this.ocean.update(this.camera, this.lod, this.cullingBounds());
    } else {
      // Each model culls its chunks to its own strip's frustum, so its vertex work too is its
      // strip's share. Bands and seams depend on distance alone (ChunkSelector), so every
      // chunk that can reach the strip is the same chunk the model alone would draw there.
      const width = this.renderer.getDrawingBufferSize(this.bufferSize).x;
      const chunks = [this.ocean, ...this.sides.map((side) => side.chunks)];
      const bounds = [this.cullingBounds(), ...this.sides.map((side) => side.bounds())];
      // A chunk straddling a strip's frustum is drawn as only the tiles that reach the strip
      // (OceanChunks, TILES): a chunk across a divider costs each model its own side's triangles.
      strips.forEach((strip, i) => {
        if (strip.x1 > strip.x0) chunks[i].update(this.stripCamera(strip, width), this.lod, bounds[i], this.stripCulling);
      });
    }
    const inWater = this.where.submersion !== 'above';
    this.material.setSeenFromBelow(this.where.submersion === 'below' && !this.underwaterShortcuts ? 'straddling' : this.where.submersion);
    this.seaBed.mesh.visible = inWater;
    this.seaBed.follow(this.camera.position);
    // Seen entirely from below, the sky can only show through the surface: skip drawing it.
    this.skyBackground.mesh.visible = this.where.submersion !== 'below';
    setEyeDepth(this.waterVolume, eyeSurface - this.camera.position.y);
  }

  /**
   * The underwater passes, built on first use. Their code (the composer, its passes and
   * shaders) is fetched only when the camera first goes below the surface; until it has
   * arrived this returns undefined, the canvas keeps its last frame, and `redraw` is called
   * once it is there.
   */
  private underwaterPost(): UnderwaterPost | undefined {
    if (!this.post && this.underwaterCode) {
      this.post = new this.underwaterCode.UnderwaterPost(this.renderer, this.scene, this.camera, this.waveBinding, { ...this.waterVolume, ...this.light });
      const size = this.renderer.getSize(new Vector2());
      this.post.setSize(size.x, size.y, this.renderer.getPixelRatio());
      this.post.setBlur(this.params.blurStrength);
      this.post.setGodRays(this.params.godRays ? this.params.godRaysIntensity : 0);
      this.post.forceShaftLightWindow = this.shaftLightWindowForced;
    }
    this.underwaterLoad ??= import('../underwater/underwaterPost').then(
      (code) => {
        this.underwaterCode = code;
        this.redraw();
      },
      () => {
        // The sea is still drawn from below, plainly (no water fog, god rays or blur), rather
        // than the canvas keeping its last frame above water. The browser keeps a failed
        // module import failed, so only a reload tries again.
        this.underwaterFailed = true;
        this.partFailed();
        this.redraw();
      },
    );
    return this.post;
  }

  /** Settles once the underwater passes have loaded, when a frame has needed them; at once otherwise. */
  whenPartsLoaded(): Promise<void> {
    return this.underwaterLoad ?? Promise.resolve();
  }

  /** Submits the frame prepared by update(): directly above water, through the composer below it. */
  draw(): void {
    this.renderer.info.reset();
    const { underwater, submersion } = this.where;
    let composerPasses = 0;
    if (this.post && (submersion === 'above' || this.showHeightmaps || this.underwaterFailed)) encodeSceneForPost(this.scene, false);
    if (this.showHeightmaps) this.heightmapView = this.drawHeightmaps();
    else if (submersion === 'above' && this.sides.length > 0) this.drawCompare(this.splitStrips() ?? []);
    else if (submersion === 'above') this.renderer.render(this.scene, this.camera);
    else if (this.underwaterFailed) this.renderer.render(this.scene, this.camera);
    else composerPasses = this.underwaterPost()?.render(submersion === 'straddling') ?? 0;
    const info = this.renderer.info.render;
    // Wireframe draws each ocean triangle as three line segments (three.js's wireframe index), counted as lines.
    const triangles = info.triangles + (this.material.wireframe ? Math.round(info.lines / 3) : 0);
    this.lastStats = { drawCalls: info.calls, triangles, ...this.ocean.stats(), underwater, submersion, composerPasses };
  }

  /**
   * compare=a,b[,c] above the water: the scene once per model, each with only its own ocean
   * shown, the viewport the whole canvas and the scissor its strip of columns. Every pixel is
   * drawn by exactly one model, with the projection of the whole view, so a strip holds the
   * same pixels as that model drawn alone; its fragment work is its strip's share. (Below the
   * water the first model is drawn alone: the underwater passes are not split.)
   */
  private drawCompare(strips: readonly Strip[], afterStrip?: (model: string) => void): void {
    const size = this.renderer.getDrawingBufferSize(this.bufferSize);
    const ratio = this.renderer.getPixelRatio();
    const groups = [this.ocean.group, ...this.sides.map((side) => side.chunks.group)];
    const names = [this.waveView.name, ...this.sides.map((side) => side.name)];
    this.renderer.setScissorTest(true);
    try {
      strips.forEach((strip, i) => {
        if (strip.x1 <= strip.x0) return;
        groups.forEach((group, j) => (group.visible = i === j));
        // three multiplies the scissor by the pixel ratio and rounds: whole buffer pixels come back.
        this.renderer.setScissor(strip.x0 / ratio, 0, (strip.x1 - strip.x0) / ratio, size.y / ratio);
        this.renderer.render(this.scene, this.camera);
        afterStrip?.(names[i]);
      });
    } finally {
      this.renderer.setScissorTest(false);
      groups.forEach((group, j) => (group.visible = j === 0));
    }
  }

  /** The strips of a split frame (compare= above the water, not the heightmap view); null for a whole frame. */
  private splitStrips(): Strip[] | null {
    if (this.sides.length === 0 || this.showHeightmaps || this.where.submersion !== 'above') return null;
    const width = this.renderer.getDrawingBufferSize(this.bufferSize).x;
    return compareStrips(this.sides.length + 1, this.params.compareSplit, this.params.compareSplit2, width);
  }

  /** The view's camera narrowed to one strip's columns (setViewOffset): the frustum a strip's chunks are culled with. */
  private stripCamera(strip: Strip, width: number): PerspectiveCamera {
    const camera = this.cullCamera.copy(this.camera);
    // The full height from the camera's own aspect (setViewOffset sets aspect = width / height),
    // so a fractional pixel ratio's rounded buffer cannot narrow the frustum.
    const fullHeight = width / this.camera.aspect;
    camera.setViewOffset(width, fullHeight, strip.x0, 0, strip.x1 - strip.x0, fullHeight);
    camera.updateMatrixWorld();
    return camera;
  }

  /** The active model's heightmaps; a model without any shows a clear screen. */
  private drawHeightmaps(): HeightmapView | undefined {
    const textures = this.waveView.heightmapTextures;
    if (!textures) {
      this.renderer.clear();
      return this.heightmapView;
    }
    const view = this.heightmapView ?? new HeightmapView();
    view.render(this.renderer, textures, this.camera.aspect, this.waveView.heightmapLayout);
    return view;
  }

  /** Waits for every GPU command so far: reading one canvas pixel cannot finish before them. */
  waitForGpu(): void {
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, this.syncPixel);
  }

  /**
   * Draws one frame waiting for the GPU after each pass, and returns each pass's time.
   * Above the water the frame is the single direct render, reported as 'scene', or with
   * compare= one render per strip, 'scene <model> strip'; a model with GPU passes of its own
   * (waves=fft: 'fft', 'foam'; a compared one's with its name) reports those first.
   */
  profileFrame(time: number): PassTiming[] {
    const gl = this.renderer.getContext();
    const pixel = new Uint8Array(4);
    // Reading a canvas pixel waits for every command before it; each pass binds its own target again.
    const sync = () => {
      this.renderer.setRenderTarget(null);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    };
    this.update(time);
    // The wave model's own GPU passes (the FFTs), redone at the same time, come first.
    const wavePasses = this.waveView.profilePasses?.(sync) ?? [];
    const { submersion } = this.where;
    if (submersion !== 'above') {
      const post = this.underwaterPost();
      if (!post) throw new Error('The underwater passes are still loading: await oceano.ready, or draw a frame below the surface first.');
      return [...wavePasses, ...post.profile(submersion === 'straddling', sync)];
    }
    if (this.post) encodeSceneForPost(this.scene, false);
    // The side models' own GPU passes (a compared fft), then each strip alone ('scene <model>').
    for (const side of this.sides) wavePasses.push(...(side.view.profilePasses?.(sync) ?? []).map((p) => ({ ...p, name: `${p.name} (${side.name})` })));
    sync();
    let start = performance.now();
    const strips = this.splitStrips();
    if (strips) {
      const passes: PassTiming[] = [];
      this.drawCompare(strips, (model) => {
        sync();
        passes.push({ name: `scene ${model} strip`, ms: performance.now() - start });
        start = performance.now();
      });
      return [...wavePasses, ...passes];
    }
    this.renderer.render(this.scene, this.camera);
    sync();
    return [...wavePasses, { name: 'scene', ms: performance.now() - start }];
  }

  /**
   * Debug, for the negative controls of tests/browser/shading.test.ts and waterline.test.ts:
   * switch off the fixes for far and very close views, so the tests can show they catch the
   * fault each one removes.
   */
  setShadingFixes(fixes: Partial<ShadingFixes>): void {
    if (fixes.detailNormals !== undefined) this.material.setDetailNormals(fixes.detailNormals);
    if (fixes.cameraRelative !== undefined) this.material.absoluteCoordinates = !fixes.cameraRelative;
    if (fixes.seaBedMark !== undefined) this.seaBed.setWaterMark(fixes.seaBedMark);
    if (fixes.relativePixelNormals !== undefined) this.material.setAbsolutePixelNormals(!fixes.relativePixelNormals);
    if (fixes.clearanceNear !== undefined) this.clearanceNear = fixes.clearanceNear;
    if (fixes.underwaterShortcuts !== undefined) {
      this.underwaterShortcuts = fixes.underwaterShortcuts;
      this.seaBed.setDepth(this.params.seaBedDepth, this.underwaterShortcuts ? this.bounds.vertical : Infinity);
    }
  }

  /**
   * Debug: bake the shaft light as a window around the camera even where the model's lens
   * repeats, so a test can compare the path generic wave models take with the tile.
   */
  forceShaftLightWindow(on: boolean): void {
    this.shaftLightWindowForced = on;
    if (this.post) this.post.forceShaftLightWindow = on;
  }

  /**
   * The active model's GPU chunk evaluated at grid points (x, z) and a time. The probe's code
   * is fetched on first use (tests and the API use it, the picture never does).
   */
  async probeSurface(points: readonly (readonly [number, number])[], time: number): Promise<ProbeSample[]> {
    const { SurfaceProbe } = await import('../teaching/surfaceProbe');
    this.probe ??= new SurfaceProbe(this.renderer, this.waveBinding, this.wake);
    this.waveView.update(time);
    try {
      return this.probe.probe(points);
    } finally {
      this.waveView.update(this.frameTime);
    }
  }

  /**
   * Median CPU time of one full culling + LOD selection for the current camera, ms (batches
   * of 20 for timer resolution). Each is made to select afresh: a still camera's frames
   * reuse the last selection and would time only the comparison that decides it.
   */
  timeLodUpdate(batches = 25): number {
    const perBatch: number[] = [];
    for (let b = 0; b < batches; b++) {
      const start = performance.now();
      for (let k = 0; k < 20; k++) {
        this.ocean.forgetSelection();
        this.ocean.update(this.camera, this.lod, this.cullingBounds());
      }
      perBatch.push((performance.now() - start) / 20);
    }
    return median(perBatch);
  }

  /** How many times the sun's sky has been painted (0 with a page's own images). */
  skyPaintCount(): number {
    return this.sunSky?.paintCount ?? 0;
  }

  stats(): RenderStats {
    return { ...this.lastStats, lodCounts: this.lastStats.lodCounts.slice() };
  }

  dispose(): void {
    this.ocean.dispose();
    this.material.dispose();
    for (const side of this.sides) side.dispose();
    this.probe?.dispose();
    this.heightmapView?.dispose();
    this.post?.dispose();
    this.seaBed.dispose();
    this.kelvinGuide.dispose();
    this.waveView.dispose();
    this.fresnelTexture.dispose();
    this.fresnelFromBelowTexture.dispose();
    if (this.sunSky) this.sunSky.dispose();
    else this.sky.dispose();
    this.skyBackground.dispose();
    this.renderer.dispose();
  }
}

/** The model the view itself draws: the first of a comparison, else `waves`. */
function firstModel(params: OceanParams): WavesChoice {
  return compareModelNames<WavesChoice>(params.compare)[0] ?? params.waves;
}

/** The parameters an ocean material shows (every model's material of a comparison alike). */
const LOOK_KEYS: ParamKey[] = ['sunElevation', 'sunAzimuth', 'waterColor', 'fresnel', 'wireframe', 'normals', 'shading', 'normalsCompare', 'lodColors'];

function applyLook(material: OceanMaterial, params: OceanParams): void {
  material.setWaterColor(params.waterColor);
  material.setSunDirection(sunDirection(params.sunElevation, params.sunAzimuth));
  material.setFresnelEnabled(params.fresnel);
  material.setWireframe(params.wireframe);
  material.setTeachingViews(params.normals === 'flat', params.shading === 'normals');
  material.setNormalsCompare(params.normalsCompare);
  material.setLodColors(params.lodColors);
}
