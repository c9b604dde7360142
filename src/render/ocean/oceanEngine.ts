import {
  Color,
  Object3D,
  Vector3,
  type CubeTexture,
  type DataTexture,
  type IUniform,
  type PerspectiveCamera,
  type WebGLRenderer,
} from 'three';
import { defaultParams, validateParams, type OceanParams, type ParamKey } from '../../sim/params/params';
import { paramsChanged } from '../../sim/params/paramChanges';
import type { LiveWaveModel, SurfaceSample, WavesChoice } from '../../sim/waves/waveModel';
import { windrowStrength } from '../../sim/waves/fft/windrows';
import { COMPARE_OFF, compareModelNames } from '../../sim/compare/compareLayout';
import { AIR_IOR, fresnelReflectance, fresnelTable, WATER_IOR } from '../../sim/optics/fresnel';
import { SUN_LIGHT_COLOR, sunDirection } from '../../sim/optics/sun';
import { fresnelTableFromBelow, refractedSunDirection, type Submersion } from '../../sim/underwater/snellWindow';
import type { WakeUniformData } from '../../sim/wake/wakeUniformData';
import { addWake } from '../../sim/wake/boatWake';
import { createWaterVolumeUniforms, applyWaterVolume, setEyeDepth, type WaterVolumeUniforms } from '../underwater/waterVolumeUniforms';
import { applyCaustics, createCausticsUniforms, type CausticsUniforms } from '../underwater/causticsUniforms';
import { SeaBed } from '../underwater/seaBed';
import { lightWithCaustics } from '../underwater/hullCaustics';
import { fresnelTexture } from '../optics/dataTextures';
import { WaveBinding } from '../waves/waveBinding';
import { BASE_STEP, nearBandRefinement } from '../../sim/lod/lodBands';
import { createWaveModelView, loadWaveModels, modelsDrawn, modelsMissing } from '../waves/waveViewRegistry';
import type { WaveModelView } from '../waves/waveModelView';
import { applyWakeUniforms, createWakeUniforms } from '../wake/wakeUniforms';
import { SkySource } from '../sky/skySource';
import type { SkyBackground } from '../sky/skyBackground';
import type { OceanMaterialInputs } from '../compare/compareSide';
import { OceanMaterial } from './oceanMaterial';
import type { BoatInField, InteractiveWaves } from '../iwave/interactiveWaves';
import { createInteractiveWaveUniforms } from '../iwave/interactiveWaveUniforms';
import { IWAVE_MAX_HEIGHT } from '../../sim/iwave/fieldSize';
import type { DisturbanceOptions } from '../../sim/iwave/disturbanceChecks';
import type { Stone } from '../../sim/iwave/iwaveGrid';
import { message, MessageError, type Message } from '../../sim/params/message';
import { OceanChunks, type LodSettings } from '../lod/oceanChunks';
import { EyeSubmersion, type EyePlace } from './eyeSubmersion';
import { createFoamUniforms, setFoamWind } from '../foam/foamUniforms';
import { checkSurfaceBatch, sampleSurfaces, type SurfacePoints, type SurfaceSamples } from '../../sim/waves/surfaceBatch';
import type { FoamDetail } from '../foam/foamDetail';
import type { CoastScene } from '../coast/coastScene';
import type { SailLimit } from '../../sim/coast/aground';

/** @internal The parameters an ocean material shows (every model's material of a comparison alike). */
export const LOOK_KEYS: readonly ParamKey[] = [
  'sunElevation',
  'sunAzimuth',
  'waterColor',
  'waterColorPicked',
  'fresnel',
  'seaRoughness',
  'skyBlur',
  'wireframe',
  'normals',
  'shading',
  'normalsCompare',
  'lodColors',
  'subsurface',
  'waveGroups',
  'windrows',
  'windSpeed',
  'visibility',
];

/**
 * The machinery of the ocean, which the app drives piece by piece and the library's `Ocean`
 * (ocean.ts) wraps: the active wave model (its GPU half and its CPU twin), the chunked sea
 * with its levels of detail and culling, the sky it reflects, and the sea bed seen from
 * under the water. Its surface at rest is the plane y = 0 of the world (the sea's own frame).
 * Members tagged internal are the app's and the diagnostics': the published types leave them out.
 */
export class OceanEngine extends Object3D {
  /** The sky the sea reflects, drawn behind everything: add it to your scene if you want it as the background. */
  readonly sky: Object3D;
  /** Every load started so far (whenReady). */
  private loading: Promise<void> = Promise.resolve();
  /** @internal */
  readonly fresnelData = fresnelTable(256);
  /** @internal */
  readonly fresnelFromBelowData = fresnelTableFromBelow(256);
  /** @internal */
  readonly chunks: OceanChunks;
  /** @internal */
  readonly material: OceanMaterial;
  /** @internal */
  readonly seaBed: SeaBed;
  /** @internal Uniforms the underwater passes share with the ocean: the water volume, the refracted sun and the sun's colour. */
  readonly lightUniforms: WaterVolumeUniforms & Record<'uRefractedSun' | 'uSunColor', IUniform>;
  /** @internal */
  readonly wakeUniforms = createWakeUniforms();
  /** @internal The interactive waves' field and grid, for the ocean's shaders (read only while interactiveWaves is on). */
  readonly interactiveWaveUniforms = createInteractiveWaveUniforms();
  /** @internal The foam material's detail texture and the wind its streaks follow, for every ocean material of the view. */
  readonly foamUniforms = createFoamUniforms();
  /** @internal What a compared model's ocean material shares with this one's. */
  readonly materialInputs: OceanMaterialInputs;
  /** @internal */
  readonly binding: WaveBinding;
  /** @internal Where the last update found the eye; 'above' before the first. */
  place: EyePlace = { underwater: false, submersion: 'above', eyeSurface: 0 };
  /** @internal The shortcuts for a view wholly under the water (back faces only, the sea bed's test skipped); a negative control turns them off. */
  underwaterShortcuts = true;
  /** @internal The height of the sea at rest, metres, in the world: Ocean.update sets it from position.y (the app's stays 0). */
  seaLevel = 0;
  private waveView: WaveModelView;
  private readonly skySource: SkySource;
  private readonly renderer: WebGLRenderer;
  private readonly fresnelTextures: { fromAbove: DataTexture; fromBelow: DataTexture };
  private readonly waterVolume: WaterVolumeUniforms = createWaterVolumeUniforms();
  private readonly caustics: CausticsUniforms = createCausticsUniforms();
  private readonly eye = new EyeSubmersion();
  private params: OceanParams;
  private applied: OceanParams | null = null;
  private lod: LodSettings;
  private bounds: { vertical: number; horizontal: number };
  private wakeBound = 0;
  private appliedWake: WakeUniformData | null = null;
  private frameTime = 0;
  private disposed = false;
  private interactive: InteractiveWaves | null = null;
  private boat: BoatInField | null = null;
  /** Stones recorded while the interactive waves' code is on its way. */
  private stonesDue: Stone[] = [];
  private foamDetail: FoamDetail | null = null;
  private foamDetailLoad: Promise<void> | null = null;
  private wakeCodeLoad: Promise<void> | null = null;
  /** @internal The coast (src/render/coast/coastScene.ts), while `bathymetry` is not `deep` and its code has arrived. */
  coast: CoastScene | null = null;
  private coastCode: Promise<void> | null = null;
  private coastScene: typeof CoastScene | null = null;

  /** `params`: validated as the URL and the GUI validate them; `sky`: a cube map to reflect, or null for the sky painted from the sun. */
  constructor(renderer: WebGLRenderer, params: Partial<OceanParams> = {}, sky: CubeTexture | null = null) {
    super();
    this.name = 'oceano-ocean';
    this.renderer = renderer;
    const full = { ...defaultParams(), ...validateParams(params) };
    this.params = full;
    this.skySource = new SkySource(sky);
    this.sky = this.skySource.background.mesh;
    this.waitFor(this.skySource.background.ready);
    const first = firstModel(full);
    // A model whose code has not arrived yet: the seed's sea stands in, hidden, until it has.
    const available = modelsMissing([first]).length === 0 ? first : 'seed';
    this.waveView = createWaveModelView({ ...full, waves: available }, renderer);
    this.binding = new WaveBinding(this.waveView);
    this.fresnelTextures = { fromAbove: fresnelTexture(this.fresnelData), fromBelow: fresnelTexture(this.fresnelFromBelowData) };
    this.lightUniforms = {
      ...this.waterVolume,
      uRefractedSun: { value: new Vector3() },
      uSunColor: { value: new Color(...SUN_LIGHT_COLOR) },
    };
    this.materialInputs = {
      fresnelTables: this.fresnelTextures,
      sky: this.skySource.texture,
      late: this.binding.late,
      shared: {
        ...this.waterVolume,
        ...this.wakeUniforms,
        ...this.interactiveWaveUniforms,
        ...this.foamUniforms,
        uSunColor: this.lightUniforms.uSunColor,
      },
    };
    this.material = new OceanMaterial(this.binding, this.fresnelTextures, this.skySource.texture, this.materialInputs.shared);
    this.waitFor(this.material.ready);
    this.chunks = new OceanChunks(this.material);
    this.add(this.chunks.group);
    this.lod = full;
    this.bounds = this.waveView.model.bounds();
    this.seaBed = new SeaBed(this.binding, { ...this.waterVolume, ...this.caustics, ...this.lightUniforms });
    this.add(this.seaBed.mesh);
    this.visible = available === first;
    // Until the first model's code arrives, the stand-in's parameters are the ones in force.
    this.apply(this.visible ? full : { ...full, waves: available, compare: COMPARE_OFF });
    if (!this.visible) this.waitFor(this.loadModels(full));
  }

  /**
   * Settles once every load started so far has finished: the wave model's code, the sky, the
   * parts fetched on first use. The ocean stays hidden until its model's code is here. A load
   * started later (a setParams that asks for another model) is covered by a later call.
   */
  whenReady(): Promise<void> {
    return this.loading;
  }

  private waitFor(load: Promise<unknown> | null): void {
    this.loading = Promise.all([this.loading, load]).then(() => undefined);
  }

  /** @internal The CPU twin of the waves drawn: sample it for heights and normals at any time. */
  get waves(): LiveWaveModel {
    return this.coast?.surfaceOver(this.waveView.model) ?? this.waveView.model;
  }

  /** The time of the last update, seconds. */
  get time(): number {
    return this.frameTime;
  }

  /** @internal The interactive waves while interactiveWaves is on, else null. */
  get interactiveWaves(): InteractiveWaves | null {
    return this.interactive;
  }

  /** @internal The GPU half of the waves drawn. */
  get waveModelView(): WaveModelView {
    return this.waveView;
  }

  /** @internal The sky texture the sea reflects. */
  get skyTexture(): CubeTexture {
    return this.skySource.texture;
  }

  /** @internal The sky drawn behind the scene (its mesh is `sky`). */
  get skyBackground(): SkyBackground {
    return this.skySource.background;
  }

  /** @internal The levels of detail and culling settings in force. */
  get lodSettings(): LodSettings {
    return this.lod;
  }

  /** @internal Every parameter in force, the app's too. */
  getAllParams(): OceanParams {
    return { ...this.params };
  }

  /** @internal Changes any subset of the parameters, validated exactly as the URL and the GUI validate them (a bad value throws, naming it). */
  setParams(partial: Partial<OceanParams>): void {
    const next = { ...this.params, ...validateParams(partial) };
    if (modelsMissing([firstModel(next)]).length > 0) {
      this.waitFor(this.loadModels(next));
      return;
    }
    this.apply(next);
  }

  private loadModels(params: OceanParams): Promise<void> {
    this.params = params;
    return loadWaveModels([firstModel(params)]).then(() => {
      if (this.params !== params) return;
      this.apply(params);
      this.visible = true;
      // The foam's detail texture and the wake's code, asked for as the model arrived, are part of being ready.
      return Promise.all([this.foamDetail ? undefined : this.foamDetailLoad, this.wakeCodeLoad]).then(() => undefined);
    });
  }

  /**
   * Applies the parameters that differ from the last ones applied (all of them the first
   * time): the frame loop may call it every frame, and nothing is re-uploaded unless it changed.
   * The first model's code must have been loaded (loadWaveModels).
   * @internal
   */
  apply(params: OceanParams): void {
    const before = this.applied;
    const changed = (...keys: ParamKey[]) => paramsChanged(before, params, keys);
    this.applied = { ...params };
    this.params = params;
    const first = firstModel(params);
    if (first !== this.waveView.name) {
      const previous = this.waveView;
      this.waveView = createWaveModelView({ ...params, waves: first }, this.renderer);
      this.binding.setModel(this.waveView);
      previous.dispose();
    }
    this.waveView.setParams(params);
    // The seed too: it draws the phases of the coast's swell components.
    if (changed('bathymetry', 'beachSlope', 'depth', 'swellHeight', 'swellPeriod', 'swellDirection', 'windSea', 'seed'))
      this.setCoast(params);
    // Chunk boxes reach as far as any wave can move a vertex (the coast's swell included), so a crest rising into view is never culled.
    this.bounds = this.waves.bounds();
    if (changed('seed')) this.seaBed.setNoiseSeed(params.seed);
    if (changed('sunElevation', 'sunAzimuth', 'waterColor', 'waterColorPicked', 'fogDensity', 'caustics', 'causticsIntensity')) {
      const sun = sunDirection(params.sunElevation, params.sunAzimuth);
      this.skySource.paint(this.renderer, sun);
      (this.lightUniforms.uRefractedSun.value as Vector3).fromArray(refractedSunDirection(sun) ?? [0, 0, 0]);
      applyWaterVolume(this.waterVolume, params.waterColor, params.waterColorPicked, sun[1], params.fogDensity);
      applyCaustics(this.caustics, sun, params.caustics, params.causticsIntensity);
      this.seaBed.setSunTransmission(1 - fresnelReflectance(Math.max(0, sun[1]), AIR_IOR, WATER_IOR));
    }
    if (changed(...LOOK_KEYS)) applyLook(this.material, params);
    if (changed('interactiveWaves')) this.setInteractiveWaves(params.interactiveWaves);
    this.interactive?.setEquation(params.iwaveEquation);
    this.interactive?.setGuide(params.iwaveGuide);
    if (params.wake || params.interactiveWaves) this.loadWakeCode();
    if (changed('windDirection')) setFoamWind(this.foamUniforms, params.windDirection);
    this.setFoamTexture(foamTextureWanted(params));
    if (changed('lodDistance', 'lodBands', 'lodBruteForce', 'freezeCulling', 'lodMorph')) {
      this.lod = {
        lodDistance: params.lodDistance,
        lodBands: params.lodBands,
        lodBruteForce: params.lodBruteForce,
        freezeCulling: params.freezeCulling,
        lodMorph: params.lodMorph,
      };
    }
    // The wave bound too: a bed below every trough skips the caustics' above-the-surface test.
    // On a coast the bed follows the floor (shaders/coast.glsl) and rises through the waves.
    const coast = this.coast?.active ?? false;
    this.seaBed.setDepth(coast ? 0 : params.seaBedDepth, this.underwaterShortcuts && !coast ? this.bounds.vertical : Infinity);
  }

  /**
   * The coast's code is fetched the first time `bathymetry` is not `deep` (most oceans are
   * deep); whenReady() covers it. Deep again, the coast is taken away and its programs left out.
   */
  private setCoast(params: OceanParams): void {
    if (params.bathymetry === 'deep') {
      this.coast?.dispose();
      this.coast = null;
      return;
    }
    if (this.coastScene) {
      this.waitFor(this.buildCoast(params));
      return;
    }
    this.coastCode ??= import('../coast/coastScene').then(({ CoastScene }) => {
      this.coastScene = CoastScene;
      if (!this.disposed && this.params.bathymetry !== 'deep') return this.buildCoast(this.params);
    });
    this.waitFor(this.coastCode);
  }

  /** The coast of `params`, its field built in a Worker: settles when it is drawn, the culling bound grown by its swell. */
  private buildCoast(params: OceanParams): Promise<void> {
    const coast = (this.coast ??= new this.coastScene!(this));
    return coast.setParams(params).then(() => {
      if (this.coast === coast) this.bounds = this.waves.bounds();
    });
  }

  /** @internal Where a boat may sail: on a coast it stops aground (src/sim/coast/aground.ts); null on the open sea. */
  get sailLimit(): SailLimit | null {
    return this.coast?.sailLimit ?? null;
  }

  /** Everything a frame needs for `camera` at `time` (seconds): the waves, which side of the water the eye is on, and the chunks in view. */
  update(time: number, camera: PerspectiveCamera): void {
    this.follow(camera);
    this.advance(time);
    this.locateEye(camera, time);
    this.cull(camera);
    this.shade(camera);
  }

  /** @internal Centres the interactive waves on where `camera` looks (update does; a view that calls advance itself calls this first). */
  follow(camera: PerspectiveCamera): void {
    if (this.interactive) this.interactive.follow(...focusOf(camera));
  }

  /** @internal The waves at `time`: the model's GPU passes and uniforms. */
  advance(time: number): void {
    this.frameTime = time;
    this.waveView.update(time);
    this.coast?.update(time);
    if (this.interactive) {
      this.interactive.setBoat(this.boat);
      this.interactive.advance(time);
      this.interactive.readBack();
    }
  }

  /**
   * Your boat, for the interactive waves, before each update: its hull a solid in the field that
   * pushes water at bow and stern (src/sim/iwave/movingHull.ts), and, while the analytic wake
   * is drawn too, where that wake takes over its waves. Null: no boat.
   * @internal
   */
  setBoat(boat: BoatInField | null): void {
    this.boat = boat;
  }

  /** @internal `sample` (at world (x, z)) with the interactive waves added while they are on, from their latest read-back. */
  withInteractiveWaves(sample: SurfaceSample, x: number, z: number): SurfaceSample {
    return this.interactive ? addWake(sample, this.interactive.sample(x, z)) : sample;
  }

  /**
   * The interactive waves' code is fetched the first time they are switched on (most oceans
   * never use them); whenReady() then covers them until they run.
   */
  private setInteractiveWaves(on: boolean): void {
    if (on && !this.interactive) {
      // The field's slope reaches the normals through the wake's GLSL (wakeTiltNormal): both must be here before OCEAN_IWAVE goes in.
      this.loadWakeCode();
      const start = Promise.all([import('../iwave/interactiveWaves'), this.wakeCodeLoad]).then(([{ InteractiveWaves, iwaveChunk }]) => {
        if (!this.params.interactiveWaves || this.interactive || this.disposed) return;
        this.interactive = new InteractiveWaves(this.renderer, this.interactiveWaveUniforms);
        this.interactive.setEquation(this.params.iwaveEquation);
        this.interactive.setGuide(this.params.iwaveGuide);
        this.add(this.interactive.guide.lines);
        this.interactive.record(this.stonesDue);
        this.stonesDue = [];
        this.binding.late.provide('oceano_iwave', iwaveChunk());
        this.material.setInteractiveWavesOn(true);
      });
      this.waitFor(start);
      return;
    }
    if (!on && this.interactive) {
      this.interactive.dispose();
      this.interactive = null;
    }
    this.material.setInteractiveWavesOn(on && this.interactive !== null);
  }

  /** The wake's GLSL, fetched the first time the wake or the interactive waves (whose slope reaches the pixels through it) are on; whenReady() covers it. */
  private loadWakeCode(): void {
    if (this.wakeCodeLoad) return;
    this.wakeCodeLoad = import('../wake/wakeChunk').then(({ wakeChunk }) => this.binding.late.provide('oceano_wake', wakeChunk));
    this.waitFor(this.wakeCodeLoad);
  }

  /**
   * Foam drawn as foam needs its detail texture, whose code is fetched the first time a view
   * draws foam (the spectral sea's whitecaps, the boat's wake); whenReady() then covers it until it is
   * drawn. Off, or with no foam in view, the foam is flat paint (OceanMaterial compiles the
   * material out while the texture is null).
   */
  private setFoamTexture(on: boolean): void {
    if (on && !this.foamDetail) {
      this.foamDetailLoad ??= import('../foam/foamDetail').then(({ FoamDetail, foamMaterialChunk }) => {
        if (this.disposed) return;
        this.binding.late.provide('oceano_foam', foamMaterialChunk);
        this.foamDetail = new FoamDetail(this.renderer);
        this.setFoamTexture(foamTextureWanted(this.params));
      });
      this.waitFor(this.foamDetailLoad);
      return;
    }
    this.foamUniforms.uFoamDetail.value = on && this.foamDetail ? this.foamDetail.texture : null;
    this.foamUniforms.uFoamDensityMean.value = this.foamDetail?.meanDensity ?? 0.5;
  }

  /**
   * Drops a stone at world (x, z) into the interactive waves (interactiveWaves must be on): a
   * bump of `height` metres (negative: a dip) and `radius` metres, at rest, recorded at the
   * current simulation time. Bad arguments throw a MessageError naming the argument (its
   * notice in the page's language), and change nothing; returns notices (a radius under one
   * texel is raised to one texel).
   */
  disturb(x: number, z: number, options: DisturbanceOptions = {}): Message[] {
    if (!this.interactive)
      throw new MessageError(message('disturbFieldOff'), 'disturb: the interactive waves are off (set interactiveWaves: true first).');
    return this.interactive.disturb(x, z, options);
  }

  /** @internal Stones from a record (a share link's, a preset's), each at its own time plus `after` seconds: the field is replayed to hold them. */
  recordStones(stones: readonly Stone[], after = 0): void {
    if (this.interactive) this.interactive.record(stones, after);
    else for (const [time, ...rest] of stones) this.stonesDue.push([time + after, ...rest]);
  }

  /** @internal The analytic wake's weight at world (x, z): 1 but where the interactive waves carry the boat's own (the hand-over). */
  wakeWeight(x: number, z: number): number {
    return this.interactive?.wakeWeight(x, z) ?? 1;
  }

  /** @internal Height of the surface under (x, z) at `time`, kept while nothing it depends on changes (a paused view asks it every frame). */
  surfaceUnder(x: number, z: number, time: number): number {
    return this.eye.surfaceUnder(this.waves, x, z, time);
  }

  /** @internal Which side of the water `camera` sees from. */
  locateEye(camera: PerspectiveCamera, time: number): EyePlace {
    this.place = this.eye.locate(camera, this.waves, this.bounds.vertical, time);
    return this.place;
  }

  /**
   * Chooses the chunks in `camera`'s view. `tiles`: the camera is a compare strip's, and a
   * chunk straddling it is drawn as only the tiles that reach it.
   * @internal
   */
  cull(camera: PerspectiveCamera, tiles = false): void {
    this.chunks.update(camera, this.lod, this.cullingBounds(), tiles, nearBandRefinement(this.waveView.finestVertexStep ?? BASE_STEP));
  }

  /** @internal The culling bounds: the model's, grown by the wake's. */
  cullingBounds(): { vertical: number; horizontal: number } {
    return this.grownByWake(this.bounds);
  }

  /**
   * A model's bounds grown by how far the wake and the interactive waves (the tallest stone,
   * while they are on) can raise the surface: every model drawn with this ocean's wake (a
   * compared one too) culls, and morphs its bands, with these.
   * @internal
   */
  grownByWake(bounds: { vertical: number; horizontal: number }): { vertical: number; horizontal: number } {
    const extra = this.wakeBound + (this.interactive ? IWAVE_MAX_HEIGHT : 0);
    return extra === 0 ? bounds : { vertical: bounds.vertical + extra, horizontal: bounds.horizontal };
  }

  /** @internal The shading for where the eye is: which faces, the sea bed, the sky behind, the water between the eye and the surface. */
  shade(camera: PerspectiveCamera): void {
    const { submersion, eyeSurface } = this.place;
    this.material.setSeenFromBelow(submersion === 'below' && !this.underwaterShortcuts ? 'straddling' : submersion);
    this.seaBed.mesh.visible = submersion !== 'above';
    this.seaBed.follow(camera.position);
    this.coast?.shade(submersion);
    // Seen entirely from below, the sky can only show through the surface.
    this.sky.visible = submersion !== 'below';
    setEyeDepth(this.waterVolume, eyeSurface - camera.position.y);
  }

  /** Which side of the water the last update's camera saw from: 'above', 'below', or 'straddling' (the waterline crosses its near plane). */
  get submersion(): Submersion {
    return this.place.submersion;
  }

  /**
   * Height and normal of the surface at (x, z) of the sea's own frame, by the CPU twin, at the last update's time unless `time` is given;
   * with the interactive waves on, their latest read-back added (a frame or two old, whatever `time` says).
   */
  sampleSurface(x: number, z: number, time = this.frameTime): SurfaceSample {
    return this.withInteractiveWaves(this.waves.sample(x, z, time), x, z);
  }

  /**
   * @internal sampleSurface for many points at `time` (Ocean.sampleSurfaces chooses it): `points`
   * holds x, z pairs (metres, the sea's own frame), `out` receives per point [height (metres), nx,
   * ny, nz], each equal to sampleSurface's (as float32 in a Float32Array). A new Float32Array
   * unless you pass one to reuse; bad input throws a TypeError.
   */
  sampleSurfacesAt(points: SurfacePoints, out?: SurfaceSamples, time = this.frameTime): SurfaceSamples {
    const into = checkSurfaceBatch(points, out);
    return sampleSurfaces(this.waves, points, time, into, this.interactive ? (s, x, z) => this.withInteractiveWaves(s, x, z) : null);
  }

  /** @internal The boat's wake for the coming frame (src/sim/wake/boatWake.ts packs it) and how far it can raise the surface, metres. */
  setWake(data: WakeUniformData, bound: number): void {
    if (data !== this.appliedWake) applyWakeUniforms(this.wakeUniforms, data);
    this.appliedWake = data;
    this.wakeBound = bound;
  }

  /** @internal Lets the sunlight on a model of yours (a boat) pass through the waves: caustics on its wet side. */
  lightWithCaustics(model: Object3D): void {
    lightWithCaustics(model, this.binding, this.caustics);
  }

  /** Reflects a cube map of yours from now on (the sun then moves only the lighting). */
  setSky(sky: CubeTexture): void {
    this.skySource.setCustom(sky);
    this.materialInputs.sky = sky;
    this.material.setSky(sky);
  }

  /** @internal After a lost WebGL context comes back: paints again what lived only in render targets. */
  contextRestored(): void {
    this.chunks.forgetSelection();
    this.material.contextRestored();
    this.waveView.contextRestored?.();
    this.interactive?.contextRestored();
    this.foamDetail?.draw(this.renderer);
    this.skySource.contextRestored(this.renderer, sunDirection(this.params.sunElevation, this.params.sunAzimuth));
  }

  dispose(): void {
    this.disposed = true;
    this.removeFromParent();
    this.sky.removeFromParent();
    this.chunks.dispose();
    this.coast?.dispose();
    this.material.dispose();
    this.seaBed.dispose();
    this.waveView.dispose();
    this.interactive?.dispose();
    this.foamDetail?.dispose();
    this.binding.dispose();
    this.fresnelTextures.fromAbove.dispose();
    this.fresnelTextures.fromBelow.dispose();
    this.skySource.dispose();
  }
}

/**
 * The point the interactive waves centre on: where the camera's line of sight meets the sea
 * (y = 0) within 60 m, else the point 60 m along its heading, else the camera's own (x, z).
 */
function focusOf(camera: PerspectiveCamera): [number, number] {
  const forward = camera.getWorldDirection(new Vector3());
  const { x, y, z } = camera.position;
  const reach = forward.y < 0 ? Math.min(-y / forward.y, 60) : 60;
  const horizontal = Math.hypot(forward.x, forward.z);
  if (horizontal < 1e-6) return [x, z];
  return [x + forward.x * reach, z + forward.z * reach];
}

/** Whether foam is drawn as foam: the spectral sea's whitecaps, the wake's foam or the coast's surf in view, and the foamTexture parameter on. */
function foamTextureWanted(params: OceanParams): boolean {
  return params.foamTexture && ((params.foam && modelsDrawn(params).includes('fft')) || params.wake || params.bathymetry !== 'deep');
}

/** @internal The model the ocean itself draws: the first of a comparison, else `waves`. */
export function firstModel(params: Pick<OceanParams, 'waves' | 'compare'>): WavesChoice {
  return compareModelNames<WavesChoice>(params.compare)[0] ?? params.waves;
}

/** @internal */
export function applyLook(material: OceanMaterial, params: OceanParams): void {
  material.setWaterColor(params.waterColor);
  material.setWaterColorPicked(params.waterColorPicked);
  material.setSunDirection(sunDirection(params.sunElevation, params.sunAzimuth));
  material.setFresnelEnabled(params.fresnel);
  material.setSmoothSea(!params.seaRoughness);
  material.setSkyBlur(params.skyBlur);
  material.setWireframe(params.wireframe);
  material.setTeachingViews(params.normals === 'flat', params.shading === 'normals');
  material.setNormalsCompare(params.normalsCompare);
  material.setLodColors(params.lodColors);
  material.setSubsurface(params.subsurface);
  material.setWaveGroups(params.waveGroups);
  // Only in a wind strong enough to draw them: below Beaufort 7 the field would cost its hashes for nothing.
  material.setWindrows(params.windrows && windrowStrength(params.windSpeed) > 0);
  material.setVisibility(params.visibility);
}
