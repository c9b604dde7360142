import type { CoastField, CoastSetting } from '../../src/sim/coast/coastField';
import { OFFSHORE_DEPTH } from '../../src/sim/coast/bathymetry';
import { coastSwellDisplacement, sampleCoastField } from '../../src/sim/coast/coastFieldSampling';

/**
 * Measurements of the coast's swell made on the drawn surface, as an observer with a tape and a
 * stopwatch would make them: crests located on η, heights as max − min over a period.
 */

/** η at (x, z, t), read from the displacement the renderer uses. */
export const surfaceHeight = (field: CoastField, x: number, z: number, time = 0): number => coastSwellDisplacement(field, x, z, time)[1];

/**
 * The x of every crest (local maximum of η at t = 0) on the line z between x0 and x1, sampled
 * every `step` metres and refined by a parabola through the three samples around each maximum.
 */
export function crestsAlongX(field: CoastField, z: number, x0: number, x1: number, step = 0.05): number[] {
  const crests: number[] = [];
  if (!Number.isFinite(x0) || !Number.isFinite(x1)) throw new Error(`no line to search: ${x0} to ${x1}`);
  let before = surfaceHeight(field, x0 - step, z);
  let here = surfaceHeight(field, x0, z);
  for (let x = x0; x <= x1; x += step) {
    const after = surfaceHeight(field, x + step, z);
    if (here > before && here >= after && here > 0) {
      const curvature = before - 2 * here + after;
      crests.push(x + (curvature !== 0 ? (0.5 * step * (before - after)) / curvature : 0));
    }
    before = here;
    here = after;
  }
  return crests;
}

/**
 * The x of every point on the line z (between x0 and x1, at t = 0) where η falls through zero
 * going shoreward: the front flank of each crest, a line parallel to the crest that, unlike
 * the crest's top, does not move where the amplitude changes across the wave.
 */
export function crestFrontsAlongX(field: CoastField, z: number, x0: number, x1: number, step = 0.05): number[] {
  if (!Number.isFinite(x0) || !Number.isFinite(x1)) throw new Error(`no line to search: ${x0} to ${x1}`);
  const fronts: number[] = [];
  let before = surfaceHeight(field, x0, z);
  for (let x = x0 + step; x <= x1; x += step) {
    const here = surfaceHeight(field, x, z);
    if (before > 0 && here <= 0) fronts.push(x - step + (step * before) / (before - here));
    before = here;
  }
  return fronts;
}

/** The crest front (see crestFrontsAlongX) nearest to x0 on the line z, searched within ±halfWidth. */
export function crestFrontNear(field: CoastField, x0: number, z: number, halfWidth: number): number {
  const crests = crestFrontsAlongX(field, z, x0 - halfWidth, x0 + halfWidth);
  return crests.reduce((best, x) => (Math.abs(x - x0) < Math.abs(best - x0) ? x : best), Number.POSITIVE_INFINITY);
}

/** The wave height at (x, z) of a one-component field: the highest minus the lowest η over its period, from `samples` instants. */
export function heightOverPeriod(field: CoastField, x: number, z: number, samples = 96): number {
  const period = (2 * Math.PI) / field.components[0].angularFrequency;
  let high = Number.NEGATIVE_INFINITY;
  let low = Number.POSITIVE_INFINITY;
  for (let s = 0; s < samples; s++) {
    const eta = surfaceHeight(field, x, z, (s / samples) * period);
    high = Math.max(high, eta);
    low = Math.min(low, eta);
  }
  return high - low;
}

/** ∇S at (x, z) by central differences of the sampled phase, `step` metres either side. */
export function phaseGradient(field: CoastField, x: number, z: number, step: number): [number, number] {
  const phase = (px: number, pz: number): number => sampleCoastField(field, px, pz).phase;
  return [(phase(x + step, z) - phase(x - step, z)) / (2 * step), (phase(x, z + step) - phase(x, z - step)) / (2 * step)];
}

/** |a − b| / b. */
export const relativeError = (measured: number, expected: number): number => Math.abs(measured - expected) / Math.abs(expected);

/** The beach the tests measure: slope 0.02, a 1 m, 10 s swell arriving at 30° in 60 m of water (seed 1 for its spectrum's phases). */
export const TEST_BEACH: CoastSetting = {
  bathymetry: 'beach',
  beachSlope: 0.02,
  deepDepth: OFFSHORE_DEPTH,
  swellHeight: 1,
  swellPeriod: 10,
  swellDirection: 30,
  seed: 1,
};
