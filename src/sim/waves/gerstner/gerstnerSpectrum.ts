import { seededRandom } from '../../noise/integerHash';
import { GRAVITY } from '../seed/seedSurface';
import type { GerstnerWave } from './gerstnerWaves';

/**
 * Draws N Gerstner waves from a wind spectrum, so a Gerstner sea and an FFT sea with the
 * same seed, wind and spectrum have the same character. The spectrum, the spreading and
 * the dispersion relation are passed in as functions: this file owns no spectrum formula
 * (PM, JONSWAP and Phillips live with the FFT model).
 */

/** One-sided frequency spectrum S(ω), m²·s/rad: ∫ S dω = m₀, the variance of the elevation. */
export type FrequencySpectrum = (omega: number) => number;
/**
 * Directional spreading D(θ; ω), θ in radians from the wind direction, ∫ D dθ over (−π, π] = 1
 * (it need not be normalised here: directions are drawn from its numerical CDF).
 */
export type DirectionalSpreading = (theta: number, omega: number) => number;
/** Dispersion relation ω(k), rad/s for k in rad/m; must increase with k. */
export type Dispersion = (k: number) => number;

/**
 * Linear-wave dispersion ω² = g k tanh(k h) (e.g. Stewart, Introduction to Physical
 * Oceanography, ch. 16); depth h = Infinity gives deep water, ω² = g k. A local copy so
 * this model runs without the FFT model's module; pass that one in when it exists.
 */
export function linearDispersion(depth = Infinity, gravity = GRAVITY): Dispersion {
  return (k) => Math.sqrt(gravity * k * (Number.isFinite(depth) ? Math.tanh(k * depth) : 1));
}

/** k such that dispersion(k) = ω, by bisection on a bracket that doubles until it holds ω. */
export function wavenumberFor(omega: number, dispersion: Dispersion): number {
  let lo = 0;
  let hi = (omega * omega) / GRAVITY;
  while (dispersion(hi) < omega) {
    lo = hi;
    hi *= 2;
  }
  // 80 halvings bring any bracket below double precision.
  for (let i = 0; i < 80 && hi - lo > 1e-15 * hi; i++) {
    const mid = 0.5 * (lo + hi);
    if (dispersion(mid) < omega) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

export interface GerstnerSeaOptions {
  /** Number of waves, 4–64 (params.gerstnerCount). */
  count: number;
  seed: number;
  spectrum: FrequencySpectrum;
  spreading: DirectionalSpreading;
  /** Direction the wind blows toward, radians, counted from +x toward +z. */
  windDirection: number;
  /** Q in [0, 1] (params.gerstnerSteepness): the share of the looping limit the sea may use. */
  steepness: number;
  dispersion?: Dispersion;
  /**
   * The band of the spectrum the waves sample, as quantiles of its energy. The default
   * keeps 98.9 % of m₀: the last 1 % of a ω⁻⁵ tail lies at such high frequency that one
   * wave standing for it would be a short, steep ripple that eats the whole steepness budget.
   */
  energyBand?: [number, number];
  /** Where S(ω) is integrated to find the band, rad/s. */
  omegaSearch?: [number, number];
}

const TWO_PI = 2 * Math.PI;
const DEFAULT_BAND: [number, number] = [0.001, 0.99];
const DEFAULT_SEARCH: [number, number] = [0.01, 40];
/** Points of the numerical CDFs; enough that a CDF step is far below one wave's share. */
const CDF_POINTS = 4096;
const DIRECTION_POINTS = 720;

/** Cumulative trapezoid integral of f over xs, normalised to end at 1. */
function cumulative(xs: Float64Array, f: (x: number) => number): Float64Array {
  const cdf = new Float64Array(xs.length);
  let prev = f(xs[0]);
  for (let i = 1; i < xs.length; i++) {
    const value = f(xs[i]);
    cdf[i] = cdf[i - 1] + 0.5 * (prev + value) * (xs[i] - xs[i - 1]);
    prev = value;
  }
  const total = cdf[cdf.length - 1];
  if (!(total > 0)) throw new Error('The spectrum or spreading integrates to zero: no waves to draw.');
  for (let i = 0; i < cdf.length; i++) cdf[i] /= total;
  return cdf;
}

/** x where the increasing cdf over xs reaches u, interpolated linearly. */
function invert(xs: Float64Array, cdf: Float64Array, u: number): number {
  let lo = 0;
  let hi = cdf.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (cdf[mid] < u) lo = mid;
    else hi = mid;
  }
  const span = cdf[hi] - cdf[lo];
  const f = span > 0 ? (u - cdf[lo]) / span : 0;
  return xs[lo] + f * (xs[hi] - xs[lo]);
}

/**
 * The waves, before the steepness limit:
 * - Frequencies by stratified sampling of the spectrum's energy: the band is cut into N
 *   slices of equal energy and wave i takes a seeded random frequency inside slice i (the
 *   "equal-energy" discretisation). Every wave then carries the same variance m₀ᴮ / N, so
 *   Σ Aᵢ² / 2 = m₀ᴮ, the band's share of m₀ exactly, and the random place inside each slice
 *   keeps the frequencies incommensurate, so the sea never repeats (equally spaced ωᵢ
 *   would repeat every 2π / Δω).
 * - Direction: wind direction plus an angle drawn from D(θ; ωᵢ) by its numerical CDF.
 * - Phase: uniform on [0, 1) turns.
 * - k from ω by inverting the dispersion relation.
 * All randomness comes from the seed, in a fixed order (frequency, direction, phase per wave).
 */
export function drawGerstnerWaves(options: GerstnerSeaOptions): GerstnerWave[] {
  const { count, seed, spectrum, spreading, windDirection } = options;
  if (!Number.isInteger(count) || count < 1) throw new Error(`Wave count must be a positive integer, got ${count}.`);
  const dispersion = options.dispersion ?? linearDispersion();
  const [bandLo, bandHi] = options.energyBand ?? DEFAULT_BAND;
  const [searchLo, searchHi] = options.omegaSearch ?? DEFAULT_SEARCH;

  // A log grid: spectra span decades in ω and are sharp near their peak.
  const omegas = new Float64Array(CDF_POINTS);
  for (let i = 0; i < CDF_POINTS; i++) omegas[i] = searchLo * Math.pow(searchHi / searchLo, i / (CDF_POINTS - 1));
  const energyCdf = cumulative(omegas, spectrum);
  let m0 = 0;
  for (let i = 1; i < CDF_POINTS; i++) m0 += 0.5 * (spectrum(omegas[i]) + spectrum(omegas[i - 1])) * (omegas[i] - omegas[i - 1]);
  const amplitude = Math.sqrt((2 * m0 * (bandHi - bandLo)) / count);

  const thetas = new Float64Array(DIRECTION_POINTS + 1);
  for (let i = 0; i <= DIRECTION_POINTS; i++) thetas[i] = -Math.PI + (TWO_PI * i) / DIRECTION_POINTS;

  const random = seededRandom(seed);
  const waves: GerstnerWave[] = [];
  for (let i = 0; i < count; i++) {
    const u = bandLo + ((i + random()) / count) * (bandHi - bandLo);
    const omega = invert(omegas, energyCdf, u);
    const directionCdf = cumulative(thetas, (theta) => spreading(theta, omega));
    const heading = windDirection + invert(thetas, directionCdf, random());
    const phase = random();
    const k = wavenumberFor(omega, dispersion);
    const c = k / TWO_PI;
    waves.push({ cx: c * Math.cos(heading), cz: c * Math.sin(heading), omega, amplitude, horizontal: amplitude, phase });
  }
  return waves;
}

/**
 * Sets every wave's horizontal amplitude Qᵢ Aᵢ so that Σ Qᵢ kᵢ Aᵢ ≤ steepness ≤ 1.
 *
 * Why crests never loop: the horizontal map p ↦ p + Dₕ(p) has Jacobian
 *   J = I − Σ Qᵢ kᵢ Aᵢ cos θᵢ k̂ᵢ k̂ᵢᵀ.
 * Each k̂ k̂ᵀ has eigenvalues 0 and 1, so the sum's eigenvalues lie within ±Σ Qᵢ kᵢ Aᵢ |cos θᵢ|,
 * and J's eigenvalues stay ≥ 1 − Σ Qᵢ kᵢ Aᵢ. While that is ≥ 0, det J ≥ 0 everywhere: the
 * map never folds, so neighbouring grid points never swap places and the surface never
 * turns over itself into a loop. At exactly 1 the steepest possible crest (all waves
 * cresting together along one line) is a cusp, the limiting trochoid. The same bound makes
 * the fixed-point inversion p ← q − Dₕ(p) a contraction with rate ≤ Σ Qᵢ kᵢ Aᵢ, since its
 * derivative is I − J.
 *
 * How Q is shared: every wave gets the same Qᵢ = steepness · min(1, 1 / Σ kⱼ Aⱼ). So Q = 1
 * is Gerstner's own trochoid (Qᵢ = 1, circular orbits) unless the sea is steep enough that
 * that would loop, and then the largest Qᵢ that cannot. One Qᵢ for all waves is the
 * choppiness λ of Tessendorf's FFT sea (D = −iλ k̂ h), so both models sharpen crests alike.
 * (GPU Gems ch. 1 uses Qᵢ = Q / (kᵢ Aᵢ N) instead, which gives short waves Qᵢ ≫ 1.)
 */
export function limitSteepness(waves: readonly GerstnerWave[], steepness: number): GerstnerWave[] {
  if (!(steepness >= 0 && steepness <= 1)) throw new Error(`Steepness Q must lie in [0, 1], got ${steepness}.`);
  let slopeSum = 0;
  for (const w of waves) slopeSum += TWO_PI * Math.hypot(w.cx, w.cz) * w.amplitude;
  const q = steepness * Math.min(1, slopeSum > 0 ? 1 / slopeSum : 1);
  return waves.map((w) => ({ ...w, horizontal: q * w.amplitude }));
}

/** drawGerstnerWaves followed by limitSteepness: the sea params.gerstnerCount and gerstnerSteepness describe. */
export function gerstnerSea(options: GerstnerSeaOptions): GerstnerWave[] {
  return limitSteepness(drawGerstnerWaves(options), options.steepness);
}
