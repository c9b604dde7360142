import { integerNoise } from './integerHash';

/** Perlin's quintic fade, 6t⁵ − 15t⁴ + 10t³: flat at both ends, so the noise's slope is continuous across cells. */
function quintic(t: number): number {
  return t * t * t * (t * (t * 6 - 15) + 10);
}

/**
 * One octave of value noise on the integer lattice of (u, v), in [−1, 1): each lattice point's
 * value is integerNoise of its cell (no period within 2³² cells), blended by the quintic fade.
 * The GLSL twin is foamValueNoise in shaders/foam/foamBreakup.glsl.
 */
export function valueNoise(u: number, v: number, seed: number): number {
  const i = Math.floor(u);
  const j = Math.floor(v);
  const wu = quintic(u - i);
  const wv = quintic(v - j);
  const a = integerNoise(i, j, seed);
  const b = integerNoise(i + 1, j, seed);
  const c = integerNoise(i, j + 1, seed);
  const d = integerNoise(i + 1, j + 1, seed);
  const top = a + (b - a) * wu;
  const bottom = c + (d - c) * wu;
  return top + (bottom - top) * wv;
}
