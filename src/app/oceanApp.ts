import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { CubeTexture } from 'three';
import { validateParams, type OceanParams } from '../sim/params';
import { OceanSurface, type SurfaceSample } from '../sim/oceanSurface';
import { sunDirection } from '../sim/sun';
import { OceanView } from '../render/oceanView';
import type { PassTiming } from '../render/underwaterPost';
import type { Submersion } from '../sim/underwater';
import { loadSkyCube, paintedSkyCube } from '../render/skyCube';
import { ControlPanel } from './controlPanel';
import { Notices } from './notices';
import { SimulationClock } from './simulationClock';
import type { UrlState } from './urlState';

/** How often a frame is followed by a GPU sync to measure its full cost (frames). */
const SYNC_EVERY = 8;
const FRAME_SAMPLES = 30;

export interface CameraPose {
  position: [number, number, number];
  target: [number, number, number];
}

export interface OceanStats {
  frameMs: number;
  drawCalls: number;
  triangles: number;
  /** The camera is below the surface at its own (x, z), by the CPU twin of the waves. */
  underwater: boolean;
  /** 'straddling': the waterline may cross the frame and is decided per pixel. */
  submersion: Submersion;
  /** EffectComposer passes run for the last frame; 0 above the water. */
  composerPasses: number;
}

/** The default view, and the one "Surface" returns to. */
const DEFAULT_POSE: CameraPose = { position: [0, 9, 40], target: [0, 0, -60] };
/** Where "Dive" puts the eye, metres below the mean sea level, and how far ahead it looks. */
const DIVE_DEPTH = 6;
const DIVE_LOOK_AHEAD = 60;

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

  /** Builds the scene and draws the first frame; resolves once it is on screen. */
  async start(): Promise<void> {
    const sky = await this.loadSky();
    this.view = new OceanView(this.canvas, this.surface, sky, this.params);
    this.controls = new OrbitControls(this.view.camera, this.canvas);
    // The whole sphere around the target: orbiting below its level takes the eye under the water.
    this.controls.maxPolarAngle = Math.PI;
    this.setCamera({ position: this.url.camera ?? DEFAULT_POSE.position, target: this.url.target ?? DEFAULT_POSE.target });
    this.panel = new ControlPanel(this.container, this.params, this.clock.playing, {
      onParam: (key, value) => this.setParams({ [key]: value }),
      onPlayingChange: (playing) => (playing ? this.play() : this.pause()),
      onDive: () => this.dive(),
      onSurface: () => this.setCamera(DEFAULT_POSE),
    });
    this.resize();
    new ResizeObserver(() => this.resize()).observe(this.canvas);
    this.renderFrame();
    this.animationHandle = requestAnimationFrame(this.loop);
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
    this.view.render(this.clock.time);
    this.frameCount++;
    if (!sync) return;
    const gl = this.view.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    this.frameTimes.push(performance.now() - start);
    if (this.frameTimes.length > FRAME_SAMPLES) this.frameTimes.shift();
  }

  getParams(): OceanParams {
    return { ...this.params };
  }

  /** Validates the whole update before applying any of it; throws a ParamError naming the bad key. */
  setParams(partial: unknown): OceanParams {
    const valid = validateParams(partial);
    this.params = { ...this.params, ...valid };
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
    return { frameMs, ...this.view.stats() };
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

  dispose(): void {
    cancelAnimationFrame(this.animationHandle);
    this.controls.dispose();
    this.panel?.dispose();
    this.view.dispose();
  }
}
