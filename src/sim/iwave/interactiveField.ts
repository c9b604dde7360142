import { GRAVITY } from './iwaveGrid';
import { fittedVerticalDerivativeKernel, waveEquationKernel, type ConvolutionKernel } from './verticalDerivativeKernel';

import {
  IWAVE_CATCH_UP_STEPS,
  IWAVE_DAMPING,
  IWAVE_GRID_SIZE,
  IWAVE_MAX_HEIGHT,
  IWAVE_MAX_RADIUS,
  IWAVE_SPACING,
  IWAVE_STEP,
} from './fieldSize';
import { smoothstep } from '../math/smoothstep';

export { IWAVE_CATCH_UP_STEPS, IWAVE_DAMPING, IWAVE_GRID_SIZE, IWAVE_MAX_HEIGHT, IWAVE_MAX_RADIUS, IWAVE_SPACING, IWAVE_STEP };
export { checkDisturbance, type DisturbanceOptions } from './disturbanceChecks';

/**
 * The plain wave equation's speed where it stands in for iWave or beside it (the
 * stone-compare preset): the phase speed √(g/k) of a 1.5 rad/m wave, mid-band, 2.56 m/s.
 */
export const WAVE_EQUATION_SPEED = Math.sqrt(GRAVITY / 1.5);

/** Which equation the field solves: deep water's (iWave), the plain wave equation, or iWave left of the middle and the wave equation right of it. */
export type IWaveEquation = 'dispersive' | 'non-dispersive' | 'side-by-side';

/** The kernels for an equation: the one of every texel (or of the left half), and the right half's, if split. */
export function equationKernels(
  equation: IWaveEquation,
  spacing = IWAVE_SPACING,
): { kernel: ConvolutionKernel; rightKernel: ConvolutionKernel | null } {
  const wave = () => waveEquationKernel(WAVE_EQUATION_SPEED, spacing, GRAVITY);
  if (equation === 'non-dispersive') return { kernel: wave(), rightKernel: null };
  return { kernel: fittedVerticalDerivativeKernel(), rightKernel: equation === 'side-by-side' ? wave() : null };
}

/** A read-back of the field: heights every `stride` floats (RGBA: 4), n × n row by row along z, around (centerX, centerZ). */
export interface FieldSnapshot {
  heights: Float32Array;
  stride: number;
  n: number;
  spacing: number;
  centerX: number;
  centerZ: number;
}

/**
 * (h, ∂h/∂x, ∂h/∂z) of a field snapshot at world (x, z): the CPU twin of
 * iwaveHeightAndGradient in shaders/iwave.glsl (bilinear between texel centres, slopes by
 * central differences one texel apart, faded out over the outer tenth of the square).
 */
export function sampleField(field: FieldSnapshot, x: number, z: number): [number, number, number] {
  const { n, spacing } = field;
  const halfWidth = 0.5 * n * spacing;
  const fromX = x - field.centerX;
  const fromZ = z - field.centerZ;
  const edge = Math.max(Math.abs(fromX), Math.abs(fromZ)) / halfWidth;
  const fade = 1 - smoothstep(0.9, 1, edge);
  if (fade <= 0) return [0, 0, 0];
  const u = fromX / spacing + n / 2 - 0.5;
  const v = fromZ / spacing + n / 2 - 0.5;
  const at = (i: number, j: number) => (i < 0 || j < 0 || i >= n || j >= n ? 0 : field.heights[(j * n + i) * field.stride]);
  const bilinear = (a: number, b: number) => {
    const i = Math.floor(a);
    const j = Math.floor(b);
    const fa = a - i;
    const fb = b - j;
    return (at(i, j) * (1 - fa) + at(i + 1, j) * fa) * (1 - fb) + (at(i, j + 1) * (1 - fa) + at(i + 1, j + 1) * fa) * fb;
  };
  const h = bilinear(u, v);
  const dx = (bilinear(u + 1, v) - bilinear(u - 1, v)) / (2 * spacing);
  const dz = (bilinear(u, v + 1) - bilinear(u, v - 1)) / (2 * spacing);
  return [fade * h, fade * dx, fade * dz];
}
