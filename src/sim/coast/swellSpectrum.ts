import { seededRandom } from '../noise/integerHash';
import { JONSWAP_GAMMA, jonswapWithShape } from '../waves/spectra/jonswap';

/**
 * The swell from far away as a long-crested, narrow-band spectrum: JONSWAP in frequency
 * (Hasselmann et al. 1973, eq. 2.8) with its peak at ωp = 2π / swellPeriod and significant
 * height Hs = 4 √m0 = swellHeight, sampled at SWELL_COMPONENTS frequencies that all travel in
 * swellDirection. Each component is transformed on its own by linear theory (the coast's
 * fields), and their sum beats: equal amplitudes at unequal frequencies make wave groups, the
 * surfer's sets, about 2π / Δω apart.
 */

/** How many frequencies sample the swell's spectrum: four, two per layer of the coast's texture. */
export const SWELL_COMPONENTS = 4;

/**
 * The peak enhancement γ of the swell's JONSWAP: JONSWAP's own mean, 3.3 (Hasselmann et al.
 * 1973). A chosen value: swells are often narrower still (γ up to 7 or more), and a larger γ
 * would only draw the four frequencies closer and the sets longer.
 */
export const SWELL_PEAK_ENHANCEMENT = JONSWAP_GAMMA;

/**
 * The band the components are drawn from, in units of ωp: below 0.5 ωp JONSWAP holds
 * e^(−20) of its peak's density, and above 3 ωp the ω⁻⁵ tail holds about 1 % of m0.
 */
export const SWELL_BAND: readonly [number, number] = [0.5, 3];

/** One frequency of the swell: η_m = a cos(S_m(x) − ω t + φ). */
export interface SwellComponentSpec {
  /** ω, rad/s. */
  angularFrequency: number;
  /** a offshore, metres. */
  amplitude: number;
  /** φ, radians: where in its cycle the component starts, drawn from the seed. */
  phaseOffset: number;
}

export interface SwellSpectrumSettings {
  /** Hs = 4 √m0, metres. */
  swellHeight: number;
  /** Tp = 2π / ωp, seconds. */
  swellPeriod: number;
  /** The app's seed: the same seed gives the same phases, and so the same sets. */
  seed: number;
}

/** JONSWAP's shape at ω for a peak ωp (α = 1: only the shape matters here, the height comes from Hs). */
export function swellSpectralShape(omega: number, peak: number, gamma = SWELL_PEAK_ENHANCEMENT): number {
  return jonswapWithShape(omega, 1, peak, gamma);
}

/** Steps of the trapezoid rule across SWELL_BAND: fine enough that the bins' edges sit to 1e-4 ωp. */
const BAND_STEPS = 20_000;

/**
 * The energy-weighted mean frequency of each of `count` bins that hold equal shares of the
 * spectrum's energy across SWELL_BAND: ω_m = ∫ ω S dω / ∫ S dω over bin m.
 */
export function equalEnergyFrequencies(peak: number, count = SWELL_COMPONENTS, gamma = SWELL_PEAK_ENHANCEMENT): number[] {
  const low = SWELL_BAND[0] * peak;
  const step = ((SWELL_BAND[1] - SWELL_BAND[0]) * peak) / BAND_STEPS;
  // Cumulative energy and first moment at each node.
  const energy = new Float64Array(BAND_STEPS + 1);
  const moment = new Float64Array(BAND_STEPS + 1);
  let previous = swellSpectralShape(low, peak, gamma);
  for (let s = 1; s <= BAND_STEPS; s++) {
    const omega = low + s * step;
    const density = swellSpectralShape(omega, peak, gamma);
    energy[s] = energy[s - 1] + 0.5 * step * (previous + density);
    moment[s] = moment[s - 1] + 0.5 * step * ((omega - step) * previous + omega * density);
    previous = density;
  }
  const total = energy[BAND_STEPS];
  const frequencies: number[] = [];
  let start = 0;
  for (let m = 1; m <= count; m++) {
    let end = start;
    while (end < BAND_STEPS && energy[end] < (m / count) * total) end++;
    if (m === count) end = BAND_STEPS;
    frequencies.push((moment[end] - moment[start]) / (energy[end] - energy[start]));
    start = end;
  }
  return frequencies;
}

/**
 * The swell's components: SWELL_COMPONENTS frequencies from equal-energy bins, each of
 * amplitude a = √(2 m0 / K) so that Σ a² / 2 = m0 = (Hs / 4)², and a phase offset per
 * component drawn from the seed.
 */
export function swellComponents(settings: SwellSpectrumSettings, count = SWELL_COMPONENTS): SwellComponentSpec[] {
  const peak = (2 * Math.PI) / settings.swellPeriod;
  const m0 = (settings.swellHeight / 4) ** 2;
  const amplitude = Math.sqrt((2 * m0) / count);
  const random = seededRandom(settings.seed);
  return equalEnergyFrequencies(peak, count).map((angularFrequency) => ({
    angularFrequency,
    amplitude,
    phaseOffset: 2 * Math.PI * random(),
  }));
}

/**
 * A regular swell: one component of height swellHeight (a = H / 2) at ω = 2π / swellPeriod.
 * Linear theory's wave train as the textbooks draw it, which the coast's tests measure.
 */
export function regularSwell(settings: Pick<SwellSpectrumSettings, 'swellHeight' | 'swellPeriod'>): SwellComponentSpec[] {
  return [{ angularFrequency: (2 * Math.PI) / settings.swellPeriod, amplitude: settings.swellHeight / 2, phaseOffset: 0 }];
}

/**
 * How long a set takes to come round, seconds: the beat period 2π / Δω of the two neighbouring
 * components closest in frequency, the longest of the groups the sum holds (Infinity for one).
 */
export function setPeriod(components: readonly SwellComponentSpec[]): number {
  const omegas = components.map((c) => c.angularFrequency).sort((a, b) => a - b);
  let closest = Infinity;
  for (let m = 1; m < omegas.length; m++) closest = Math.min(closest, omegas[m] - omegas[m - 1]);
  // One component alone has no groups: its envelope never changes.
  return closest === Infinity ? Infinity : (2 * Math.PI) / closest;
}
