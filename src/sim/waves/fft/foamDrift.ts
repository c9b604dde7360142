import { windVector, type SeaState } from '../spectra/seaState';
import { FOAM_STEP_SECONDS, rememberFoam } from './foamMemory';

/**
 * The foam left behind floats, so the water's surface carries it: downwind at about 3 % of the
 * wind speed (American Meteorological Society, Glossary of Meteorology, "wind drift"; the same
 * share that oil-spill responders use for a slick's drift). The waves do not drift: their
 * crests are where their phases put them, so the foam slides slowly across the sea it came from.
 * The glossary's turn of about 10° to the right of the wind (left in the southern hemisphere)
 * is left out: the sea has no latitude.
 */
export const WIND_DRIFT_SHARE = 0.03;

/** The surface drift that carries the foam, m/s (x, z). */
export function foamDriftVelocity(sea: Pick<SeaState, 'windSpeed' | 'windDirection'>): [number, number] {
  const [wx, wz] = windVector(sea.windDirection);
  const speed = WIND_DRIFT_SHARE * sea.windSpeed;
  return [speed * wx, speed * wz];
}

/**
 * The remembered foam lives on the smallest cascade's texels (foamMemory.ts), so it moves by
 * whole texels: by lattice step k it has moved round(v k Δ / texel) texels, a function of k
 * alone. So a jump, which replays a window of steps from nothing, moves what it replays exactly
 * as playing did, and the memory stays the same to the bit on both paths.
 */
export function foamDriftTexels(velocity: readonly [number, number], texel: number, step: number): [number, number] {
  const metres = step * FOAM_STEP_SECONDS;
  return [Math.round((velocity[0] * metres) / texel), Math.round((velocity[1] * metres) / texel)];
}

/** The texels the memory moves in lattice step k (from step k − 1's place to step k's). */
export function foamDriftStep(velocity: readonly [number, number], texel: number, step: number): [number, number] {
  const [x, z] = foamDriftTexels(velocity, texel, step);
  const [px, pz] = foamDriftTexels(velocity, texel, step - 1);
  return [x - px, z - pz];
}

/**
 * One lattice step of a whole memory tile, n × n texels, row by row (z rows of x): each texel
 * takes what lay `shift` texels upstream (the tile wraps), faded by `decay`, or the fresh
 * potential, the larger (rememberFoam per texel). The TS twin of shaders/fftFoamMemory.frag.
 */
export function driftedMemoryStep(
  previous: Float32Array,
  fresh: Float32Array,
  n: number,
  decay: number,
  shift: readonly [number, number],
): Float32Array {
  const next = new Float32Array(n * n);
  const wrap = (i: number) => ((i % n) + n) % n;
  for (let z = 0; z < n; z++) {
    for (let x = 0; x < n; x++) {
      const from = wrap(z - shift[1]) * n + wrap(x - shift[0]);
      next[z * n + x] = rememberFoam(previous[from], fresh[z * n + x], decay);
    }
  }
  return next;
}
