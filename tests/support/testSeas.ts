import { GRAVITY } from '../../src/sim/waves/dispersion';
import { jonswapShape, jonswapWithShape } from '../../src/sim/waves/spectra/jonswap';
import { piersonMoskowitz as pmDensity, piersonMoskowitzPeak } from '../../src/sim/waves/spectra/piersonMoskowitz';
import { piersonMoskowitzHs } from '../../src/sim/physics/physicsReport';

/**
 * The app's own wind spectra (src/sim/waves/spectra/piersonMoskowitz.ts, jonswap.ts, shared with the FFT
 * sea) in the shape the Gerstner and estimator tests use: a density, its peak and, for PM,
 * the empirical Hs. No formula lives here: the tests check the one copy the app runs.
 */
export const G = GRAVITY;

export function piersonMoskowitz(u10: number): { spectrum: (omega: number) => number; peak: number; hs: number } {
  return { spectrum: (w) => pmDensity(w, u10), peak: piersonMoskowitzPeak(u10), hs: piersonMoskowitzHs(u10) };
}

export function jonswap(u10: number, fetch: number): { spectrum: (omega: number) => number; peak: number } {
  const { alpha, peak } = jonswapShape(u10, fetch);
  return { spectrum: (w) => jonswapWithShape(w, alpha, peak), peak };
}

/**
 * cos² spreading about the wind, normalised: D(θ) = (2/π) cos² θ for |θ| < π/2. A test
 * fixture (the app uses cos-2s, src/sim/waves/spectra/directionalSpreading.ts): a narrow, one-sided
 * spreading whose waves all run downwind, which the tests' hand-derived cases assume.
 */
export function cosineSquared(theta: number): number {
  return Math.abs(theta) < Math.PI / 2 ? (2 / Math.PI) * Math.cos(theta) ** 2 : 0;
}
