import { seaDepth } from './bathymetry';
import type { CoastField } from './coastField';
import { coastSwellAt, componentAt } from './coastSwellSlope';
import { breakingFraction } from './waveTransformation';

/**
 * Reading the coast's swell field at a world point, the way the GPU reads it: bilinear
 * interpolation between texel centres, as a LINEAR-filtered float texture with CLAMP_TO_EDGE
 * does, so the CPU twin and the picture agree (coastSwellSlope.ts, shaders/coast.glsl).
 */
export interface CoastSample {
  /** Component m's unwrapped phase S, radians. */
  phase: number;
  /** Component m's amplitude A (before breaking), metres. */
  amplitude: number;
  /** Water depth h, metres (≤ 0 on land), analytic. */
  depth: number;
  /**
   * The breaking fraction of the highest wave the point sees, 0–1: of the envelope's largest
   * value 2 Σ A_m, when every component is at its crest together (the set's biggest waves).
   * For one component, the breaking fraction of its wave.
   */
  breaking: number;
}

/**
 * Component `component`'s field at world (x, z). Texel (i, j)'s centre is at
 * (originX + i·spacing, originZ + j·spacing). Outside the grid the point is clamped to the
 * grid's edge (as CLAMP_TO_EDGE does) for the amplitude, and the phase goes on growing at the
 * edge's rate, measured between the edge texel and its inward neighbour: the offshore plane
 * wave continues the edge.
 */
export function sampleCoastField(field: CoastField, x: number, z: number, component = 0): CoastSample {
  const { phase, amplitude } = componentAt(field, component, x, z);
  const depth = seaDepth(field.floor, x, z);
  return { phase, amplitude, depth, breaking: breakingFraction(2 * largestEnvelope(field, x, z), depth, field.breakerIndex) };
}

/** Σ A_m at world (x, z): the swell's largest possible |Z| there, when every component is at its crest at once. */
export function largestEnvelope(field: CoastField, x: number, z: number): number {
  let sum = 0;
  for (let m = 0; m < field.components.length; m++) sum += componentAt(field, m, x, z).amplitude;
  return sum;
}

/**
 * The swell's height at world (x, z) and time t: the components summed and limited to γ h
 * (coastSwellAt). `limited` false leaves out the limit, for the tests' negative controls.
 */
export function coastSwellHeight(field: CoastField, x: number, z: number, time: number, limited = true): number {
  return coastSwellAt(field, x, z, time, limited).height;
}

/**
 * The swell's displacement of the sea's rest point (x, 0, z): vertical only, [0, η, 0].
 * Why no horizontal (Gerstner-like) part: in shallow water linear theory's horizontal excursion
 * is a / tanh(k h), larger than the vertical one, and near breaking (a k up to ~0.4 in the surf)
 * it would fold the mesh over itself. A vertical swell never folds; the surf's foam shows where
 * the real wave overturns.
 */
export function coastSwellDisplacement(field: CoastField, x: number, z: number, time: number): [number, number, number] {
  return [0, coastSwellHeight(field, x, z, time), 0];
}

/** The step of the central differences that give the normal, metres: small beside the shortest wave drawn (~5 m). */
export const NORMAL_STEP = 0.25;

/** The unit normal of the swell's surface, from central differences of η: (−∂η/∂x, 1, −∂η/∂z), normalised. */
export function coastSwellNormal(field: CoastField, x: number, z: number, time: number): [number, number, number] {
  const slopeX =
    (coastSwellHeight(field, x + NORMAL_STEP, z, time) - coastSwellHeight(field, x - NORMAL_STEP, z, time)) / (2 * NORMAL_STEP);
  const slopeZ =
    (coastSwellHeight(field, x, z + NORMAL_STEP, time) - coastSwellHeight(field, x, z - NORMAL_STEP, time)) / (2 * NORMAL_STEP);
  const length = Math.hypot(slopeX, 1, slopeZ);
  return [-slopeX / length, 1 / length, -slopeZ / length];
}
