import type { WebGLRenderer } from 'three';
import { GpuIWave } from './gpuIWave';
import {
  IWAVE_DAMPING,
  IWAVE_STEP,
  IWAVE_CATCH_UP_STEPS,
  IWAVE_GRID_SIZE,
  IWAVE_SPACING,
  checkDisturbance,
  equationKernels,
  sampleField,
  type DisturbanceOptions,
  type FieldSnapshot,
  type IWaveEquation,
} from '../../sim/iwave/interactiveField';
import type { Disturbance, Stone } from '../../sim/iwave/iwaveGrid';
import { StoneGuideView } from './stoneGuideView';
import { besideHull, hullEarlier, type MovingHull } from '../../sim/iwave/movingHull';
import type { HeightAt } from '../../sim/boat/boatPose';
import { handOverDistance, handOverWeights, type HandOver } from '../../sim/iwave/kelvinHandOver';
import type { Message } from '../../sim/params/message';
import type { InteractiveWaveUniforms } from './interactiveWaveUniforms';
export type { InteractiveWaveUniforms };
export { iwaveChunk } from './iwaveChunk';

/** The boat as the field is told of it each frame (Ocean.setBoat). */
export interface BoatInField {
  /** The hull at `time`, seconds. */
  hull: MovingHull;
  /** Radians per second its heading turns: the steps between frames and a catch-up put the hull on that arc. */
  turnRate: number;
  time: number;
  /** Whether the analytic Kelvin wake is drawn: then it takes the boat's waves over past the hand-over distance. */
  wake: boolean;
}

/** A stone in the record: the step it fell at, and the bump. */
export interface LoggedDisturbance {
  step: number;
  disturbance: Disturbance;
}

/**
 * The interactive waves as the Ocean runs them: the GPU field (GpuIWave) stepped in fixed steps
 * of simulation time, whatever the frame rate, with every disturbance recorded at the step it
 * came in. The field at a time is the same whether the clock plays, steps or jumps: a jump
 * forward runs the steps between (at most IWAVE_CATCH_UP_STEPS, else the field restarts calm
 * that many steps back); a jump back restarts calm at most that many steps back and replays the
 * recorded disturbances from there. The boat, where there is one, is a solid that pushes water
 * at every step (src/sim/iwave/movingHull.ts), on the course it holds at the latest frame.
 */
export class InteractiveWaves {
  /** The GPU field itself (its render target can be read back). */
  readonly field: GpuIWave;
  /** The step of the latest advance, and how far the field has been stepped (−∞: to be replayed from the log). */
  private now = 0;
  private step = 0;
  private readonly log: LoggedDisturbance[] = [];
  private snapshot: FieldSnapshot | null = null;
  private reading = false;
  private boat: BoatInField | null = null;
  private handOver: HandOver | null = null;
  private equation: IWaveEquation = 'dispersive';
  private guideShown = false;
  /** The iwaveGuide overlay's rings (the Ocean holds its lines). */
  readonly guide = new StoneGuideView();

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly uniforms: InteractiveWaveUniforms,
  ) {
    this.field = new GpuIWave(renderer, { n: IWAVE_GRID_SIZE, spacing: IWAVE_SPACING, damping: IWAVE_DAMPING });
    this.publish();
  }

  /** Moves the grid's centre to the texel nearest (x, z) (the camera's focus). */
  follow(x: number, z: number): void {
    this.field.recentre(x, z);
    this.publish();
  }

  /** Which equation the field solves; a change restarts it calm and replays the record with the new one. */
  setEquation(equation: IWaveEquation): void {
    if (equation === this.equation) return;
    this.equation = equation;
    const { kernel, rightKernel } = equationKernels(equation);
    this.field.setKernels(kernel, rightKernel);
    this.replay();
  }

  /** Whether the guide rings are drawn round the stones. */
  setGuide(shown: boolean): void {
    this.guideShown = shown;
  }

  /** The boat this frame, or null: from the next step on it stands in the field and pushes water. */
  setBoat(boat: BoatInField | null): void {
    this.boat = boat;
  }

  /** Advances the field to simulation time `time`, seconds. */
  advance(time: number): void {
    const target = Math.floor(time / IWAVE_STEP + 1e-9);
    this.now = target;
    if (target < this.step || target - this.step > IWAVE_CATCH_UP_STEPS) {
      this.field.clear();
      this.step = Math.max(0, target - IWAVE_CATCH_UP_STEPS);
      // Calm water with no boat pushing stays calm: start at the first stone instead.
      if (!this.pushing())
        this.step = Math.min(
          target,
          this.log.reduce((first, entry) => (entry.step >= this.step ? Math.min(first, entry.step) : first), target),
        );
      for (const entry of this.log) if (entry.step === this.step) this.field.disturb(entry.disturbance);
    }
    while (this.step < target) {
      this.field.setHull(this.hullAt((this.step + 1) * IWAVE_STEP));
      this.field.step(IWAVE_STEP);
      this.step++;
      for (const entry of this.log) if (entry.step === this.step) this.field.disturb(entry.disturbance);
    }
    const boat = this.boat;
    this.handOver = boat?.wake
      ? { x: boat.hull.x, z: boat.hull.z, distance: handOverDistance(Math.abs(boat.hull.speed), boat.hull.length) }
      : null;
    this.guide.update(
      this.guideShown,
      this.guideShown ? this.stones(time, StoneGuideView.steps) : [],
      time,
      this.equation,
      this.field.centerX,
    );
    this.publish();
  }

  private pushing(): boolean {
    return this.boat !== null && this.boat.hull.speed * this.boat.hull.strength !== 0;
  }

  /** The hull during the step that ends at `time`: the boat's latest, moved back (or on) along its arc. */
  private hullAt(time: number): MovingHull | null {
    const boat = this.boat;
    return boat ? hullEarlier(boat.hull, boat.turnRate, boat.time - time) : null;
  }

  /**
   * A stone at world (x, z): validated (checkDisturbance; bad arguments throw and change
   * nothing), recorded at the latest advance's step and applied (or left to the replay that
   * is due). Returns the notices.
   */
  disturb(x: number, z: number, options: DisturbanceOptions): Message[] {
    const { disturbance, notices } = checkDisturbance(x, z, options);
    this.log.push({ step: this.now, disturbance });
    if (this.step === this.now) this.field.disturb(disturbance);
    this.publish();
    return notices;
  }

  /**
   * Stones from a record (a share link's, a preset's), each at its own time plus `after`
   * seconds: checked as disturb() checks them (one out of range is left out), entered in the
   * log, and the field replayed from calm at its next advance so that it holds them.
   */
  record(stones: readonly Stone[], after = 0): void {
    for (const [time, x, z, radius, height] of stones) {
      try {
        this.log.push({
          step: Math.round((time + after) / IWAVE_STEP),
          disturbance: checkDisturbance(x, z, { radius, height }).disturbance,
        });
      } catch {
        continue;
      }
    }
    this.replay();
  }

  /**
   * The stones dropped in the `within` steps up to `time`, with their times: by default those
   * a replay still runs (the catch-up bound), what a share link carries.
   */
  stones(time: number, within = IWAVE_CATCH_UP_STEPS): Stone[] {
    const now = Math.floor(time / IWAVE_STEP + 1e-9);
    return this.log
      .filter((entry) => entry.step <= now && entry.step >= now - within)
      .map(({ step, disturbance: d }) => [step * IWAVE_STEP, d.x, d.z, d.radius, d.height]);
  }

  /**
   * Starts an asynchronous read-back of the whole field (one at a time; the GPU is not waited
   * for). `sample` answers from the latest that has arrived: a frame or two behind the picture.
   */
  readBack(): void {
    if (this.reading) return;
    this.reading = true;
    const n = this.field.n;
    const heights = new Float32Array(4 * n * n);
    const snapshot: FieldSnapshot = {
      heights,
      stride: 4,
      n,
      spacing: this.field.spacing,
      centerX: this.field.centerX,
      centerZ: this.field.centerZ,
    };
    this.renderer
      .readRenderTargetPixelsAsync(this.field.target, 0, 0, n, n, heights)
      .then(() => {
        this.snapshot = snapshot;
      })
      .catch(() => undefined)
      .finally(() => {
        this.reading = false;
      });
  }

  /** Whether a read-back is on its way. */
  get readBackPending(): boolean {
    return this.reading;
  }

  /**
   * (h, ∂h/∂x, ∂h/∂z) at world (x, z) from the latest read-back (zeros before the first
   * arrives), weighted as drawn: by the field's share of the hand-over to the analytic wake.
   */
  sample(x: number, z: number): [number, number, number] {
    if (!this.snapshot) return [0, 0, 0];
    const w = handOverWeights(this.handOver, x, z)[1];
    const [h, dx, dz] = sampleField(this.snapshot, x, z);
    return [w * h, w * dx, w * dz];
  }

  /**
   * The field's heights as a boat placed so feels them: read from the water beside its hull
   * (besideHull, two texels out), since under it the field is held at 0.
   */
  beside(hull: Pick<MovingHull, 'x' | 'z' | 'heading' | 'length' | 'beam'>): HeightAt {
    return besideHull((x, z) => this.sample(x, z)[0], hull, 2 * IWAVE_SPACING);
  }

  /** The analytic wake's weight at world (x, z): 1 but near a boat whose waves the field carries. */
  wakeWeight(x: number, z: number): number {
    return handOverWeights(this.handOver, x, z)[0];
  }

  /** After a lost WebGL context comes back: the field lived in render targets, so it is run again from the log at the next advance. */
  contextRestored(): void {
    this.replay();
    this.snapshot = null;
  }

  private replay(): void {
    this.step = Number.NEGATIVE_INFINITY;
  }

  private publish(): void {
    this.uniforms.uIWaveField.value = this.field.texture;
    this.uniforms.uIWaveGrid.value.set(this.field.centerX, this.field.centerZ, IWAVE_SPACING, IWAVE_GRID_SIZE);
    const h = this.handOver;
    this.uniforms.uIWaveHandOver.value.set(h?.x ?? 0, h?.z ?? 0, h?.distance ?? 0, h ? 1 : 0);
  }

  dispose(): void {
    this.field.dispose();
    this.guide.dispose();
    this.uniforms.uIWaveField.value = null;
  }
}
