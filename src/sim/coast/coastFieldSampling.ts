import type { CoastField } from './coastField';

/**
 * Reading the coast's swell field at a world point, the way the GPU reads it: bilinear
 * interpolation between texel centres, as a LINEAR-filtered float texture with CLAMP_TO_EDGE
 * does, so the CPU twin and the picture agree. The GLSL port is the same few lines.
 */
export interface CoastSample {
  /** Unwrapped phase S, radians. */
  phase: number;
  /** Amplitude a, metres. */
  amplitude: number;
  /** Water depth h, metres (≤ 0 on land). */
  depth: number;
  /** Breaking fraction, 0–1. */
  breaking: number;
}

/** One channel (0 phase, 1 amplitude, 2 depth, 3 breaking) at texel-index coordinates (u, v), inside [0, N − 1]². */
function bilinear(field: CoastField, u: number, v: number, channel: number): number {
  const last = field.resolution - 1;
  const i0 = Math.min(Math.floor(u), last - 1);
  const j0 = Math.min(Math.floor(v), last - 1);
  const fu = u - i0;
  const fv = v - j0;
  const at = (i: number, j: number): number => field.texels[(j * field.resolution + i) * 4 + channel];
  const bottom = at(i0, j0) * (1 - fu) + at(i0 + 1, j0) * fu;
  const top = at(i0, j0 + 1) * (1 - fu) + at(i0 + 1, j0 + 1) * fu;
  return bottom * (1 - fv) + top * fv;
}

/**
 * The field at world (x, z). Texel (i, j)'s centre is at (originX + i·spacing, originZ + j·spacing).
 * Outside the grid the point is clamped to the grid's edge (as CLAMP_TO_EDGE does) for the
 * amplitude, depth and breaking, and the phase goes on growing at the edge's rate, measured
 * between the edge texel and its inward neighbour: the offshore plane wave continues the edge.
 */
export function sampleCoastField(field: CoastField, x: number, z: number): CoastSample {
  const last = field.resolution - 1;
  const u = (x - field.originX) / field.spacing;
  const v = (z - field.originZ) / field.spacing;
  const cu = Math.min(last, Math.max(0, u));
  const cv = Math.min(last, Math.max(0, v));
  let phase = bilinear(field, cu, cv, 0);
  const edgePhase = phase;
  if (u !== cu) {
    const inward = u > cu ? -1 : 1;
    phase += (edgePhase - bilinear(field, cu + inward, cv, 0)) * -inward * (u - cu);
  }
  if (v !== cv) {
    const inward = v > cv ? -1 : 1;
    phase += (edgePhase - bilinear(field, cu, cv + inward, 0)) * -inward * (v - cv);
  }
  return {
    phase,
    amplitude: bilinear(field, cu, cv, 1),
    depth: bilinear(field, cu, cv, 2),
    breaking: bilinear(field, cu, cv, 3),
  };
}

/**
 * The swell's height at world (x, z) and time t: η = a cos(S − ω t).
 * On the GPU, t is taken modulo the swell's period T (ω T = 2π) so a float32 time stays exact.
 */
export function coastSwellHeight(field: CoastField, x: number, z: number, time: number): number {
  const { phase, amplitude } = sampleCoastField(field, x, z);
  return amplitude * Math.cos(phase - field.angularFrequency * time);
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
