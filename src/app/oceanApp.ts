import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { CubeTexture } from 'three';
import { validateParams, type OceanParams } from '../sim/params';
import { OceanSurface, type SurfaceSample } from '../sim/oceanSurface';
import { sunDirection } from '../sim/sun';
import { surfaceHeight } from '../sim/surface';
import { BoatMotion, type BoatMotionState } from '../sim/boatMotion';
import type { HullSize } from '../sim/boatPose';
import { OceanView } from '../render/oceanView';
import { BoatView } from '../render/boatView';
import { loadBoatModel } from '../render/boatModel';
import { loadSkyCube, paintedSkyCube } from '../render/skyCube';
import { ControlPanel } from './controlPanel';
import { BoatSteering } from './boatSteering';
import { Notices } from './notices';
import { SimulationClock } from './simulationClock';
import type { UrlState } from './urlState';

/** How often a frame is followed by a GPU sync to measure its full cost (frames). */
const SYNC_EVERY = 8;
const FRAME_SAMPLES = 30;
/** The shipped model, relative to the page. */
const DEFAULT_BOAT_MODEL = 'models/boat.glb';
/** Hull used to float the boat until (or unless) its model gives the real size: the shipped model's. */
const NOMINAL_HULL: HullSize = { length: 8, beam: 2.6 };
const DEG = Math.PI / 180;

export interface CameraPose {
  position: [number, number, number];
  target: [number, number, number];
}

export interface OceanStats {
  frameMs: number;
  /**
   * Median CPU time of the boat's update per frame (five surface samples, damping, pose), ms.
   * Browsers round performance.now() to 0.1 ms without cross-origin isolation, so a reading
   * of 0.1 is an upper bound; `npx tsx scripts/bench-boat.ts` resolves it (a few µs).
   */
  boatMs: number;
  drawCalls: number;
  triangles: number;
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

/**
 * The page's ocean: owns the clock, the parameters, the view and the controls, and runs
 * the frame loop. The automation API is a thin layer over its public methods.
 */
export class OceanApp {
  readonly notices: Notices;
  readonly clock: SimulationClock;
  private params: OceanParams;
  private surface: OceanSurface;
  private view!: OceanView;
  private controls!: OrbitControls;
  private panel?: ControlPanel;
  private frameTimes: number[] = [];
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

  constructor(
    private readonly container: HTMLElement,
    private readonly canvas: HTMLCanvasElement,
    private readonly url: UrlState,
  ) {
    this.notices = new Notices(container);
    for (const message of url.notices) this.notices.show(message);
    this.params = url.params;
    this.clock = new SimulationClock(url.time ?? 0, url.time === null);
    this.surface = new OceanSurface(this.params);
  }

  /**
   * Builds the scene, draws the first frame and starts the loop; then loads the boat while
   * the sea runs, and resolves once a frame with the boat in it (or a notice saying why it
   * is missing) is on screen, so screenshots taken after `oceano.ready` always hold it.
   */
  async start(): Promise<void> {
    const sky = await this.loadSky();
    this.view = new OceanView(this.canvas, this.surface, sky, this.params);
    this.boatView = new BoatView(this.view.scene);
    this.controls = new OrbitControls(this.view.camera, this.canvas);
    this.controls.target.set(0, 0, -60);
    this.controls.maxPolarAngle = Math.PI * 0.495;
    this.controls.update();
    this.panel = new ControlPanel(this.container, this.params, this.clock.playing, {
      onParam: (key, value) => this.setParams({ [key]: value }),
      onPlayingChange: (playing) => (playing ? this.play() : this.pause()),
    });
    this.steering = new BoatSteering(window, (change) => this.setParams(change), () => this.params);
    this.resize();
    new ResizeObserver(() => this.resize()).observe(this.canvas);
    this.renderFrame();
    this.animationHandle = requestAnimationFrame(this.loop);
    await this.loadBoat();
    this.renderFrame(true);
  }

  private async loadBoat(): Promise<void> {
    const url = this.url.boat ?? DEFAULT_BOAT_MODEL;
    const indicator = document.createElement('div');
    indicator.className = 'oceano-loading';
    indicator.setAttribute('role', 'status');
    indicator.textContent = 'Loading the boat…';
    this.container.appendChild(indicator);
    try {
      const model = await loadBoatModel(url);
      this.hull = model.hull;
      this.boatView.setModel(model.object);
      this.boatModel = 'loaded';
    } catch (error) {
      this.boatModel = 'failed';
      this.notices.show(`${(error as Error).message} The ocean runs without the boat.`);
    } finally {
      indicator.remove();
    }
  }

  private async loadSky(): Promise<CubeTexture> {
    const base = this.url.sky ?? 'sky';
    try {
      return await loadSkyCube(base);
    } catch (error) {
      this.notices.show(`${(error as Error).message} Showing a painted sky instead.`);
      return paintedSkyCube(sunDirection(this.params.sunElevation, this.params.sunAzimuth));
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

  private resize(): void {
    const rect = this.canvas.getBoundingClientRect();
    this.view.setSize(rect.width, rect.height, Math.min(window.devicePixelRatio, 2));
  }

  /**
   * Draws one frame at the clock's time. Every SYNC_EVERY frames, and whenever called
   * from outside the loop, a one-pixel read waits for the GPU so frameMs counts GPU work.
   */
  renderFrame(sync = this.frameCount % SYNC_EVERY === 0): void {
    const start = performance.now();
    this.updateBoat();
    this.boatTimes.push(performance.now() - start);
    if (this.boatTimes.length > FRAME_SAMPLES) this.boatTimes.shift();
    this.view.render(this.clock.time);
    this.frameCount++;
    if (!sync) return;
    const gl = this.view.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    this.frameTimes.push(performance.now() - start);
    if (this.frameTimes.length > FRAME_SAMPLES) this.frameTimes.shift();
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
    this.panel?.sync(this.params, this.clock.playing);
    return this.getParams();
  }

  setTime(seconds: number): void {
    if (typeof seconds !== 'number' || !Number.isFinite(seconds)) throw new TypeError(`setTime needs a finite number of seconds, got ${String(seconds)}.`);
    this.clock.setTime(seconds);
  }

  play(): void {
    this.clock.playing = true;
    this.panel?.sync(this.params, true);
  }

  pause(): void {
    this.clock.playing = false;
    this.panel?.sync(this.params, false);
  }

  setCamera(pose: CameraPose): void {
    const finite = (v: unknown): v is [number, number, number] => Array.isArray(v) && v.length === 3 && v.every((c) => typeof c === 'number' && Number.isFinite(c));
    if (!finite(pose?.position) || !finite(pose?.target)) {
      throw new TypeError('setCamera needs { position: [x, y, z], target: [x, y, z] } with finite numbers.');
    }
    this.view.camera.position.fromArray(pose.position);
    this.controls.target.fromArray(pose.target);
    this.controls.update();
  }

  camera(): CameraPose {
    return { position: this.view.camera.position.toArray(), target: this.controls.target.toArray() as [number, number, number] };
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
    const sorted = [...this.frameTimes].sort((a, b) => a - b);
    const frameMs = sorted.length ? sorted[Math.floor(sorted.length / 2)] : 0;
    const boatSorted = [...this.boatTimes].sort((a, b) => a - b);
    const boatMs = boatSorted.length ? boatSorted[Math.floor(boatSorted.length / 2)] : 0;
    return { frameMs, boatMs, ...this.view.stats() };
  }

  fresnelTable(): Float32Array {
    return this.view.fresnelData.slice();
  }

  heightmaps(): { size: number; data: Float32Array }[] {
    return this.surface.heightmaps.map((map) => ({ size: map.size, data: map.data.slice() }));
  }

  three() {
    return { renderer: this.view.renderer, scene: this.view.scene, camera: this.view.camera };
  }

  dispose(): void {
    cancelAnimationFrame(this.animationHandle);
    this.steering?.dispose();
    this.controls.dispose();
    this.panel?.dispose();
    this.view.dispose();
  }
}
