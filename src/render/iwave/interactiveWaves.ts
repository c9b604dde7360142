import type { WebGLRenderer } from 'three';
import { GpuIWave } from './gpuIWave';
import { IWAVE_DAMPING, IWAVE_STEP, IWAVE_CATCH_UP_STEPS, IWAVE_GRID_SIZE, IWAVE_SPACING, checkDisturbance, sampleField, type DisturbanceOptions, type FieldSnapshot } from '../../sim/iwave/interactiveField';
import type { Disturbance } from '../../sim/iwave/iwaveGrid';

import type { InteractiveWaveUniforms } from './interactiveWaveUniforms';
import iwave from '../../../shaders/iwave.glsl?raw';

/** The field's GLSL for the ocean's vertices (chunk `oceano_iwave`, src/render/shaders/lateChunks.ts): it comes with this code. */
export const iwaveChunk = iwave;

export type { InteractiveWaveUniforms };

/**
 * The interactive waves as the Ocean runs them: the GPU field (GpuIWave) stepped in fixed steps
 * of simulation time, whatever the frame rate, with every disturbance recorded at the step it
 * came in. The field at a time is the same whether the clock plays, steps or jumps: a jump
 * forward runs the steps between (at most IWAVE_CATCH_UP_STEPS, else the field restarts calm
 * that many steps back); a jump back restarts calm at most that many steps back and replays the
 * recorded disturbances from there.
 */
export class InteractiveWaves {
  /** The GPU field itself (its render target can be read back). */
  readonly field: GpuIWave;
  private step = 0;
  private readonly log: { step: number; disturbance: Disturbance }[] = [];
  private snapshot: FieldSnapshot | null = null;
  private reading = false;

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

  /** Advances the field to simulation time `time`, seconds. */
  advance(time: number): void {
    const target = Math.floor(time / IWAVE_STEP + 1e-9);
    if (target < this.step || target - this.step > IWAVE_CATCH_UP_STEPS) {
      this.field.clear();
      this.step = Math.max(0, target - IWAVE_CATCH_UP_STEPS);
      for (const entry of this.log) if (entry.step === this.step) this.field.disturb(entry.disturbance);
    }
    while (this.step < target) {
      this.field.step(IWAVE_STEP);
      this.step++;
      for (const entry of this.log) if (entry.step === this.step) this.field.disturb(entry.disturbance);
    }
    this.publish();
  }

  /** A stone at world (x, z): validated (checkDisturbance), recorded at the current step and applied. Returns the notices. */
  disturb(x: number, z: number, options: DisturbanceOptions): string[] {
    const { disturbance, notices } = checkDisturbance(x, z, options);
    this.log.push({ step: this.step, disturbance });
    this.field.disturb(disturbance);
    this.publish();
    return notices;
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
    const snapshot: FieldSnapshot = { heights, stride: 4, n, spacing: this.field.spacing, centerX: this.field.centerX, centerZ: this.field.centerZ };
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

  /** (h, ∂h/∂x, ∂h/∂z) at world (x, z) from the latest read-back (zeros before the first arrives). */
  sample(x: number, z: number): [number, number, number] {
    return this.snapshot ? sampleField(this.snapshot, x, z) : [0, 0, 0];
  }

  /** After a lost WebGL context comes back: the field lived in render targets, so it is run again from the log at the next advance. */
  contextRestored(): void {
    this.step = Number.NEGATIVE_INFINITY;
    this.snapshot = null;
  }

  private publish(): void {
    this.uniforms.uIWaveField.value = this.field.texture;
    this.uniforms.uIWaveGrid.value.set(this.field.centerX, this.field.centerZ, IWAVE_SPACING, IWAVE_GRID_SIZE);
  }

  dispose(): void {
    this.field.dispose();
    this.uniforms.uIWaveField.value = null;
  }
}
