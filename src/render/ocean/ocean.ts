import { PerspectiveCamera, Quaternion, Vector3, type CubeTexture, type WebGLRenderer } from 'three';
import type { OceanParams } from '../../sim/params/params';
import { checkOceanKeys, oceanParametersOf, type OceanParameters } from '../../sim/params/oceanOptionKeys';
import type { SurfaceSample } from '../../sim/waves/waveModel';
import type { SurfacePoints, SurfaceSamples } from '../../sim/waves/surfaceBatch';
import { OceanEngine } from './oceanEngine';

/**
 * What an Ocean is made with: any subset of the parameters it reads (src/sim/params/params.ts,
 * less the app's own: src/sim/params/oceanOptionKeys.ts), and the sky it reflects. A key it
 * does not read is a type error, and an Error at run time.
 */
export interface OceanOptions extends Partial<OceanParameters> {
  /** A cube map of your own for the sea to reflect; by default the sky is painted from the sun parameters. */
  sky?: CubeTexture;
}

/**
 * The ocean as a three.js object: add it to your scene, call `update(time, camera)` before
 * each `renderer.render(scene, camera)`, and it draws itself with your camera, beside your
 * objects and lights. It changes nothing global in three.js.
 *
 * Its surface at rest is the plane y = `position.y` of the world (its world height: the sea
 * level). The sea has no edge and is level, so a turn, a scale or a sideways move of it (or of
 * a parent) cannot be honoured: update() throws on one rather than ignore it.
 *
 * Its public members are the verbs here (sampleSurfaces among them) and, from OceanEngine, `sky`, `time`, `submersion`,
 * `whenReady`, `disturb`, `setSky` and `dispose`; the rest of the engine is the app's.
 */
export class Ocean extends OceanEngine {
  /** The camera of an update moved into the sea's own frame, where the surface rests at y = 0. */
  private readonly seaCamera = new PerspectiveCamera();
  private readonly placement = { position: new Vector3(), turn: new Quaternion(), scale: new Vector3() };

  /** The parameters in `options` are validated as the URL and the GUI validate them: a bad value or a key the ocean does not read throws, naming it. */
  constructor(renderer: WebGLRenderer, options: OceanOptions = {}) {
    checkOceanKeys(options, ['sky'], 'new Ocean');
    const { sky, ...params } = options;
    super(renderer, params, sky ?? null);
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
    super.update(time, this.cameraAboveSea(camera));
  }

  /**
   * Height (world y, the sea level included) and normal of the surface at the world point
   * (x, z), by the CPU twin, at the last update's time unless `time` is given; with the
   * interactive waves on, their latest read-back added.
   */
  override sampleSurface(x: number, z: number, time?: number): SurfaceSample {
    const sample = super.sampleSurface(x, z, time);
    return { ...sample, height: sample.height + this.worldSeaLevel() };
  }

  /**
   * sampleSurface for many world points at once: `points` holds x, z pairs (metres), `out`
   * receives per point [height (world y, metres), nx, ny, nz]. A new Float32Array unless you pass
   * one to reuse; bad input throws a TypeError.
   */
  override sampleSurfaces(points: SurfacePoints, out?: SurfaceSamples, time?: number): SurfaceSamples {
    const samples = super.sampleSurfaces(points, out, time);
    const level = this.worldSeaLevel();
    if (level !== 0) for (let i = 0; i < samples.length; i += 4) samples[i] += level;
    return samples;
  }

  /** The ocean's world height, once its world transform is checked to be nothing else. */
  private worldSeaLevel(): number {
    this.updateWorldMatrix(true, false);
    const { position, turn, scale } = this.placement;
    this.matrixWorld.decompose(position, turn, scale);
    const fault = 1 - Math.abs(turn.w) > 1e-6 ? 'rotated' : Math.abs(scale.x - 1) + Math.abs(scale.y - 1) + Math.abs(scale.z - 1) > 1e-6 ? 'scaled' : Math.abs(position.x) + Math.abs(position.z) > 1e-6 ? 'moved sideways' : null;
    if (fault) throw new Error(`Ocean: it (or a parent) is ${fault}, but an endless level sea can only move up and down: set position.y, the sea level, alone.`);
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
