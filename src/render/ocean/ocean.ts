import { PerspectiveCamera, Quaternion, Vector3, type Camera, type CubeTexture, type Material, type WebGLRenderer } from 'three';
import type { OceanParams } from '../../sim/params/params';
import {
  checkOceanKeys,
  OCEAN_EXTRA_OPTIONS,
  oceanParametersOf,
  type OceanParamKey,
  type OceanParameters,
} from '../../sim/params/oceanOptionKeys';
import type { SurfaceSample } from '../../sim/waves/waveModel';
import { checkSampleOptions, type SampleSurfacesOptions, type SurfacePoints, type SurfaceSamples } from '../../sim/waves/surfaceBatch';
import { OceanEngine } from './oceanEngine';
import { CameraHook } from './cameraHook';

/**
 * What an Ocean is made with: any subset of the parameters it reads (src/sim/params/params.ts,
 * less the app's own: src/sim/params/oceanOptionKeys.ts), and the sky it reflects. A key it
 * does not read is a type error, and an Error at run time.
 */
export interface OceanOptions extends Partial<OceanParameters> {
  /** A cube map of your own for the sea to reflect; by default the sky is painted from the sun parameters. */
  sky?: CubeTexture;
  /** Sets `autoUpdate`: the ocean updates itself for every camera that renders it. Default false. */
  autoUpdate?: boolean;
}

// The run-time check's list of options beyond the parameters is OceanOptions' own, both ways.
type ExtraOption = Exclude<keyof OceanOptions, OceanParamKey>;
const extraOptionsInStep: [ExtraOption, (typeof OCEAN_EXTRA_OPTIONS)[number]] extends [(typeof OCEAN_EXTRA_OPTIONS)[number], ExtraOption]
  ? true
  : never = true;
void extraOptionsInStep;

/**
 * The ocean as a three.js object: add it to your scene, call `update(time, camera)` before
 * each `renderer.render(scene, camera)`, and it draws itself with your camera, beside your
 * objects and lights. It changes nothing global in three.js. Or set `autoUpdate`: then every
 * camera that renders it (split-screen views, a CubeCamera's six faces) gets its own update,
 * at `time`, with nothing to call.
 *
 * Its surface at rest is the plane y = `position.y` of the world (its world height: the sea
 * level). The sea has no edge and is level, so a turn, a scale or a sideways move of it (or of
 * a parent) cannot be honoured: update() throws on one rather than ignore it.
 *
 * Its public members are the verbs here (sampleSurfaces among them), `autoUpdate`, `time` and, from OceanEngine, `sky`, `submersion`,
 * `whenReady`, `disturb`, `setSky` and `dispose`; the rest of the engine is the app's.
 */
export class Ocean extends OceanEngine {
  /**
   * True: the ocean updates itself for each camera that renders it, choosing that camera's own
   * chunks and levels of detail, and the waves once a frame, at `time`. False (the default): call
   * `update(time, camera)` yourself, and every render draws the chunks chosen for that camera.
   */
  autoUpdate: boolean;
  /** The sea's time, seconds (`time`). */
  private clockTime = 0;
  /** The frame clock's reading when clockTime was last advanced or set (frameClock); NaN before the first. */
  private clockReading = Number.NaN;
  /** The time the waves were last advanced to. */
  private wavesTime = Number.NaN;
  /** The camera of an update moved into the sea's own frame, where the surface rests at y = 0. */
  private readonly seaCamera = new PerspectiveCamera();
  private readonly placement = { position: new Vector3(), turn: new Quaternion(), scale: new Vector3() };

  /** The parameters in `options` are validated as the URL and the GUI validate them: a bad value or a key the ocean does not read throws, naming it. */
  constructor(renderer: WebGLRenderer, options: OceanOptions = {}) {
    checkOceanKeys(options, OCEAN_EXTRA_OPTIONS, 'new Ocean');
    const { sky, autoUpdate, ...params } = options;
    super(renderer, params, sky ?? null);
    this.autoUpdate = autoUpdate ?? false;
    const hook = new CameraHook((camera) => this.renderedBy(camera));
    // First among the children, so that three calls it before it gathers the chunks to draw.
    hook.parent = this;
    this.children.unshift(hook);
    for (const material of [this.material, this.seaBed.material]) advanceWavesBefore(material, (drawing) => this.advanceWaves(drawing));
  }

  /**
   * The sea's time, seconds: the last update's, or what you set. With autoUpdate it runs on by
   * itself, by the page's frame clock (every render in one frame sees one time); set it to
   * drive it yourself (a clock of your own, a paused or recorded one): a value set is the time
   * of the frame it was set in, and the clock runs on from it.
   */
  override get time(): number {
    return this.clockTime;
  }

  override set time(seconds: number) {
    this.clockTime = seconds;
    this.clockReading = frameClock();
  }

  /** The parameters in force. */
  getParams(): OceanParameters {
    return oceanParametersOf(this.getAllParams());
  }

  /** Changes any subset of the parameters, validated as the constructor validates them; a model not loaded yet is fetched (whenReady). */
  override setParams(partial: Partial<OceanParameters>): void {
    checkOceanKeys(partial, [], 'Ocean.setParams');
    super.setParams(partial as Partial<OceanParams>);
  }

  /**
   * Everything a frame needs for `camera` at `time` (seconds): the waves, which side of the
   * water the eye is on, and the chunks in view, at the sea level `position.y`. Throws if the
   * ocean (or a parent) is turned, scaled or moved sideways.
   */
  override update(time: number, camera: PerspectiveCamera): void {
    this.seaLevel = this.material.seaLevel = this.worldSeaLevel();
    this.time = time;
    super.update(time, this.cameraAboveSea(camera));
    this.wavesTime = time;
  }

  /**
   * With autoUpdate, for each render: the parts of an update that depend on its camera (the
   * eye's side of the water, the chunks and bands in view, the shading for where the eye is).
   * The waves, whose GPU passes are renders of their own and cannot run while three gathers
   * this one, advance just before the sea's first draw (advanceWaves).
   */
  private renderedBy(camera: Camera): void {
    if (!this.autoUpdate || !(camera as PerspectiveCamera).isPerspectiveCamera) return;
    const reading = frameClock();
    if (reading !== this.clockReading) {
      if (!Number.isNaN(this.clockReading)) this.clockTime += (reading - this.clockReading) / 1000;
      this.clockReading = reading;
    }
    this.seaLevel = this.material.seaLevel = this.worldSeaLevel();
    const seen = this.cameraAboveSea(camera as PerspectiveCamera);
    // The interactive waves centre on the first camera of a frame.
    if (this.clockTime !== this.wavesTime) this.follow(seen);
    this.locateEye(seen, this.clockTime);
    this.cull(seen);
    this.shade(seen);
  }

  /** With autoUpdate, before the sea's first draw at a new time: the waves at that time, the render's target put back as it was. */
  private advanceWaves(renderer: WebGLRenderer): void {
    if (!this.autoUpdate || this.clockTime === this.wavesTime) return;
    this.wavesTime = this.clockTime;
    const target = renderer.getRenderTarget();
    const face = renderer.getActiveCubeFace();
    const level = renderer.getActiveMipmapLevel();
    this.advance(this.clockTime);
    renderer.setRenderTarget(target, face, level);
  }

  /**
   * Height (world y, the sea level included) and normal of the surface at the world point
   * (x, z), by the CPU twin, at the sea's `time` unless `time` is given; with the
   * interactive waves on, their latest read-back added.
   */
  override sampleSurface(x: number, z: number, time = this.clockTime): SurfaceSample {
    const sample = super.sampleSurface(x, z, time);
    return { ...sample, height: sample.height + this.worldSeaLevel() };
  }

  /**
   * sampleSurface for many world points at once, for floating bodies: `points` holds x, z pairs
   * (metres), `out` receives per point [height (world y, metres), nx, ny, nz]. A new Float32Array
   * unless you pass one to reuse; bad input throws a TypeError.
   *
   * By default it answers for the frame just drawn (at `time`) from the data that frame already
   * holds, with nothing recomputed: cheap every frame. On the FFT sea while the clock runs, the
   * CPU twin's fields come from a Worker a frame or two behind the drawn waves (the app's boat
   * rides the same). `{ time }` asks for that time exactly, each answer equal to
   * `sampleSurface(x, z, time)`; on the FFT sea that may compute its fields first (milliseconds).
   *
   * ```js
   * ocean.sampleSurfaces(points, samples); // this frame's sea, cheap
   * ocean.sampleSurfaces(points, samples, { time: 12.5 }); // exactly at t = 12.5 s
   * ```
   */
  sampleSurfaces(points: SurfacePoints, out?: SurfaceSamples, options?: SampleSurfacesOptions): SurfaceSamples {
    // Without a time: the time whose data the frame holds (the FFT twin's newest fields). Chosen
    // here, in the library's class, not in the engine the app's first load carries.
    const time = checkSampleOptions(options).time ?? this.waves.frameDataTime?.(this.time) ?? this.time;
    const samples = this.sampleSurfacesAt(points, out, time);
    const level = this.worldSeaLevel();
    if (level !== 0) for (let i = 0; i < samples.length; i += 4) samples[i] += level;
    return samples;
  }

  /** The ocean's world height, once its world transform is checked to be nothing else. */
  private worldSeaLevel(): number {
    this.updateWorldMatrix(true, false);
    const { position, turn, scale } = this.placement;
    this.matrixWorld.decompose(position, turn, scale);
    const fault =
      1 - Math.abs(turn.w) > 1e-6
        ? 'rotated'
        : Math.abs(scale.x - 1) + Math.abs(scale.y - 1) + Math.abs(scale.z - 1) > 1e-6
          ? 'scaled'
          : Math.abs(position.x) + Math.abs(position.z) > 1e-6
            ? 'moved sideways'
            : null;
    if (fault)
      throw new Error(
        `Ocean: it (or a parent) is ${fault}, but an endless level sea can only move up and down: set position.y, the sea level, alone.`,
      );
    return position.y;
  }

  /** `camera` in the sea's own frame (what the culling, the eye's side of the water and the sea bed measure in). */
  private cameraAboveSea(camera: PerspectiveCamera): PerspectiveCamera {
    if (this.seaLevel === 0 && camera.parent === null) return camera;
    const sea = this.seaCamera.copy(camera, false);
    camera.updateWorldMatrix(true, false);
    camera.matrixWorld.decompose(sea.position, sea.quaternion, sea.scale);
    sea.position.y -= this.seaLevel;
    sea.updateMatrixWorld(true);
    return sea;
  }
}

/**
 * The page's frame clock, milliseconds: the document timeline's time, which holds still within
 * a frame (so split-screen views and a CubeCamera's faces share one time); elsewhere (a worker)
 * performance.now().
 */
function frameClock(): number {
  const frame = globalThis.document?.timeline?.currentTime;
  return typeof frame === 'number' ? frame : performance.now();
}

/** Runs `before` ahead of `material`'s own onBeforeRender, with the renderer about to draw. */
function advanceWavesBefore(material: Material, before: (renderer: WebGLRenderer) => void): void {
  const own = material.onBeforeRender.bind(material);
  material.onBeforeRender = (renderer, ...rest) => {
    before(renderer);
    own(renderer, ...rest);
  };
}
