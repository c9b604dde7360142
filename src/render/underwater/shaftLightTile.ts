import type { Vec3 } from '../../sim/underwater/snellWindow';

import { GOD_RAY_RANGE } from './godRayRange';

export { GOD_RAY_RANGE };

/**
 * Texel of the baked shaft light, metres: the seed's ripple tile (96 m) at twice its
 * heightmap's resolution (256 texels), fine enough for shafts whose lens compares points
 * 1.5 m apart (SHAFT_REACH in shaders/shaftLight.frag).
 */
export const SHAFT_LIGHT_TEXEL = 0.375;

/**
 * Side of the window baked for a wave model whose lens height does not repeat on a small
 * tile, metres: the widest area the god rays can read, 2 · GOD_RAY_RANGE / cos θ_c ≈ 181.4 m
 * (θ_c the critical angle, the most a refracted sun ray can lean; see shaftLightWindow),
 * rounded up to 512 texels so the texture keeps one size whatever the sun does.
 */
export const SHAFT_LIGHT_WINDOW_TEXELS = 512;
export const SHAFT_LIGHT_WINDOW_SIDE = SHAFT_LIGHT_WINDOW_TEXELS * SHAFT_LIGHT_TEXEL;

/** What the shaft-light pass bakes this frame. */
export interface ShaftLightTile {
  /** 'tile': one period of the lens, repeating; 'window': an area around the camera, clamped. */
  kind: 'tile' | 'window';
  /** World (x, z) of the texture's corner (u = v = 0); (0, 0) for a repeating tile. */
  origin: [number, number];
  /** Side of the area the texture covers, metres. */
  extent: number;
  /** Texels per side. */
  size: number;
}

/**
 * Where the god-ray march reads the shaft light. The sunlight reaching the point p(t) = eye +
 * t·d of a line of sight crossed the surface at s(t) = p.xz − r.xz · p.y / r.y (r the
 * refracted sun, pointing down). s is linear in t: s(t) − s(0) = t (d.xz − r.xz d.y / r.y),
 * and |d.xz − r.xz d.y / r.y| ≤ √(1 − d.y²) + tan θ |d.y| ≤ √(1 + tan² θ) = 1 / |r.y| (the
 * Cauchy–Schwarz bound, reached for one d.y). With t ≤ GOD_RAY_RANGE every read lies within
 * GOD_RAY_RANGE / |r.y| of s(0): a disc whose diameter is at most 2·60 / cos θ_c, since
 * Snell's law keeps the refracted ray within the critical angle θ_c of the vertical.
 * Returns s(0), the centre, and that radius.
 */
export function shaftLightReach(eye: Vec3, refractedSun: Vec3): { centre: [number, number]; radius: number } {
  const k = eye[1] / refractedSun[1];
  return { centre: [eye[0] - refractedSun[0] * k, eye[2] - refractedSun[2] * k], radius: GOD_RAY_RANGE / Math.abs(refractedSun[1]) };
}

/**
 * The tile to bake: one period of the lens when the wave model's lens height repeats on a
 * tile no larger than the window (the seed's ripples: 96 m, 256 texels), since then one
 * tile serves every read anywhere; otherwise (a model that does not repeat, or repeats only
 * on a larger patch) a window of fixed size around the area the god rays read, its corner on
 * the texel lattice so the baked points do not crawl as the camera moves.
 */
export function planShaftLightTile(lensPeriod: number | null, eye: Vec3, refractedSun: Vec3): ShaftLightTile {
  if (lensPeriod !== null && lensPeriod <= SHAFT_LIGHT_WINDOW_SIDE) {
    const size = Math.ceil(lensPeriod / SHAFT_LIGHT_TEXEL - 1e-9);
    return { kind: 'tile', origin: [0, 0], extent: lensPeriod, size };
  }
  const half = SHAFT_LIGHT_WINDOW_SIDE / 2;
  // A sun at or below the horizon (no refracted ray, r.y ≥ 0) gets no god rays: any window does.
  const centre = refractedSun[1] < 0 ? shaftLightReach(eye, refractedSun).centre : [eye[0], eye[2]];
  const snap = (v: number) => SHAFT_LIGHT_TEXEL * Math.round((v - half) / SHAFT_LIGHT_TEXEL);
  return { kind: 'window', origin: [snap(centre[0]), snap(centre[1])], extent: SHAFT_LIGHT_WINDOW_SIDE, size: SHAFT_LIGHT_WINDOW_TEXELS };
}
