import { angularFrequency, GRAVITY } from '../waves/dispersion';
import {
  dispersionSteps,
  finish,
  fitDispersion,
  heightSeriesSteps,
  meanFrequencySpectrum,
  peakPeriod,
  significantWaveHeight,
  spectralPeak,
  type DispersionPoint,
  type HeightSampler,
  type Steps,
} from './physicsEstimators';
import { windAt19_5 } from '../waves/spectra/piersonMoskowitz';
import { seaStateFromParams, type SeaState } from '../waves/spectra/seaState';
import type { LiveWaveModel } from '../waves/waveModel';
import type { OceanParams } from '../params/params';
import { frequencySpectrum } from '../waves/spectra/waveSpectrum';
import { seaSlopeVariance, windAtHeight } from '../optics/coxMunk';
import { SUN_DISC_SLOPE_VARIANCE, unresolvedSlopeVariance } from '../optics/resolvedSlopes';

/**
 * The physics panel's figures: the running sea measured through its CPU twin (heights above
 * world points, so Gerstner's horizontal motion is undone) with src/sim/physics/physicsEstimators.ts,
 * set beside theory. Pure: the same report feeds the panel's plots and oceano.physics().
 */

/** One curve or figure's formula and where it comes from: shown as the panel's footnotes. */
export interface Citation {
  what: string;
  formula: string;
  source: string;
}

export interface PhysicsReport {
  model: 'seed' | 'gerstner' | 'fft';
  /** When the measurement started, seconds of simulated time. */
  time: number;
  dispersion: {
    /** The strongest modes measured, each with the linear theory's ω at its k. */
    points: (DispersionPoint & { theory: number })[];
    /** Power-weighted mean of ω_measured / √(g k tanh k h): 1 when the sea obeys linear dispersion. */
    fitRatio: number;
    rmsRelativeError: number;
  };
  spectrum: {
    omega: number[];
    measured: number[];
    /** The model's S(ω) at the same frequencies; null for the seed (drawn from no spectrum). */
    theory: number[] | null;
  };
  /** Spectral peak ωp, rad/s. */
  peak: { measured: number; theory: number | null };
  /** Tp = 2π / ωp, s. */
  peakPeriod: { measured: number; theory: number | null };
  /** Significant wave height, m. */
  hs: {
    /** 4 σ(η) of the height series (all the points' samples together). */
    measured: number;
    /** 4 √m₀ of the model's spectrum. */
    spectral: number | null;
    /** The empirical growth law for this spectrum (PM or JONSWAP/Hasselmann), if there is one. */
    empirical: number | null;
    empiricalName: string | null;
  };
  /**
   * The sea's mean-square slope (both horizontal directions summed) as the picture draws it:
   * what the model's normals show at full resolution, plus the Beckmann roughness the glint and
   * the sky's reflection add, against Cox & Munk's σ² for the wind.
   */
  slopes: {
    resolved: number;
    /** Cox & Munk's σ² less the resolved, never below the sun's disc (src/sim/optics/resolvedSlopes.ts). */
    roughness: number;
    total: number;
    coxMunk: number;
    /** U₁₂.₅, m/s: the wind Cox & Munk's law is read at (U₁₀ by the log profile, src/sim/optics/coxMunk.ts). */
    wind: number;
  };
  citations: Citation[];
  /** Plain-language caveats (e.g. the seed's ripples follow no dispersion law). */
  notes: string[];
}

/** What of the running sea the report reads: its name, its heights, and what it was drawn from. */
export interface MeasuredSea {
  name: PhysicsReport['model'];
  height: HeightSampler;
  /** The wind sea's state (gerstner, fft), or the seed's swell wavenumber, rad/m. */
  sea: SeaState | { swellWavenumber: number };
  /** The model's mean-square slope at a time (LiveWaveModel.slopeVariance). */
  slopeVariance(time: number): number;
  /** U₁₀, m/s: the wind the glint's roughness is read for (the seed's waves follow none, its glint does). */
  windSpeed: number;
  /** Whether the picture adds that roughness (params.seaRoughness): off, only the sun's disc. */
  seaRoughness: boolean;
}

/** The running sea as the estimators see it: heights above world points from the CPU twin. */
export function measuredSea(model: LiveWaveModel, params: OceanParams): MeasuredSea {
  const height = (x: number, z: number, t: number) => model.height(x, z, t);
  const slopes = { slopeVariance: (t: number) => model.slopeVariance(t), windSpeed: params.windSpeed, seaRoughness: params.seaRoughness };
  if (model.name === 'seed') return { name: 'seed', height, sea: { swellWavenumber: params.swellFrequency }, ...slopes };
  return { name: model.name, height, sea: seaStateFromParams(params), ...slopes };
}

/** Where the height series start: off the origin so no wave's phase is special there. */
const PROBE_POINT: [number, number] = [13.7, -4.2];
/**
 * The heights are read at PROBE_GRID² points, SERIES_LENGTH samples each (8192 in all), not
 * 8192 samples at one point: the FFT twin computes all its cascades' inverse FFTs for every new
 * time, so one point's 8192 times cost 8192 sets of FFTs; 16 points share each time's fields
 * and cost 16 times less (the timings are in docs/lessons.md). Each
 * point's series is one Welch segment, and the 16 periodograms are averaged, as the 31
 * overlapping segments of the single long series were. The points stand 1.37 and 1.61 peak
 * wavelengths apart, so they see the waves at unrelated phases.
 */
const PROBE_GRID = 4;
const SERIES_LENGTH = 512;
const WELCH_SEGMENT = 512;

function probePoints(wavelength: number): [number, number][] {
  const points: [number, number][] = [];
  for (let i = 0; i < PROBE_GRID * PROBE_GRID; i++) {
    points.push([PROBE_POINT[0] + (i % PROBE_GRID) * 1.37 * wavelength, PROBE_POINT[1] + Math.floor(i / PROBE_GRID) * 1.61 * wavelength]);
  }
  return points;
}

/**
 * Hs of a fully developed sea after Pierson & Moskowitz (1964): Hs ≈ 0.21 U₁₉.₅² / g
 * (Stewart, "Introduction to Physical Oceanography", 2008, eq. 16.31).
 */
export function piersonMoskowitzHs(windSpeed10: number): number {
  const u = windAt19_5(windSpeed10);
  return (0.21 * u * u) / GRAVITY;
}

/**
 * Hs of a fetch-limited sea, JONSWAP growth law (Hasselmann et al. 1973; as fitted in the
 * Shore Protection Manual, CERC 1984, eq. 3-33): g Hs / U₁₀² = 1.6·10⁻³ (g F / U₁₀²)^½, capped
 * at the fully developed PM value (a fetch cannot grow a sea beyond it).
 */
export function jonswapHs(windSpeed10: number, fetch: number): number {
  const u2 = windSpeed10 * windSpeed10;
  const limited = ((1.6e-3 * u2) / GRAVITY) * Math.sqrt((GRAVITY * fetch) / u2);
  return Math.min(limited, piersonMoskowitzHs(windSpeed10));
}

const DISPERSION_CITATION: Citation = {
  what: 'Dispersion',
  formula: 'ω = √(g k tanh(k h)); measured from the phase rate of the surface’s spatial Fourier modes',
  source: 'Airy linear wave theory; Tessendorf 2001, “Simulating Ocean Water”, eq. 14–15; Kinsman 1965, “Wind Waves”',
};
const WELCH_CITATION: Citation = {
  what: 'Measured S(ω)',
  formula: 'Welch periodogram, Hann window: 512 samples at each of 16 points, their periodograms averaged',
  source: 'Welch 1967, IEEE Trans. Audio Electroacoust. 15(2)',
};
const SLOPE_CITATION: Citation = {
  what: 'Slopes σ²',
  formula:
    'Cox & Munk: σ² = 0.003 + 5.12·10⁻³ U₁₂.₅, U₁₂.₅ = U₁₀ (1 + √C_D/κ ln 1.25) = 1.0201 U₁₀ (C_D = 1.3·10⁻³, κ = 0.4); roughness = σ² − resolved',
  source: 'Cox & Munk 1954, J. Opt. Soc. Am. 44(11); Bruneton, Neyret & Holzschuch 2010, Comput. Graph. Forum 29(2)',
};
const HS_CITATION: Citation = {
  what: 'Hs',
  formula: 'Hs = 4 σ(η) measured; 4 √m₀ from the spectrum',
  source: 'Holthuijsen 2007, “Waves in Oceanic and Coastal Waters”, §4.2',
};

function spectrumCitation(sea: SeaState): Citation[] {
  switch (sea.spectrum) {
    case 'pierson-moskowitz':
      return [
        {
          what: 'Spectrum (PM)',
          formula: 'S(ω) = α g² ω⁻⁵ exp(−β (g/(U₁₉.₅ ω))⁴), α = 8.1·10⁻³, β = 0.74; ωp = 0.877 g / U₁₉.₅',
          source: 'Pierson & Moskowitz 1964, J. Geophys. Res. 69(24)',
        },
        {
          what: 'Hs (PM)',
          formula: 'Hs ≈ 0.21 U₁₉.₅² / g, U₁₉.₅ ≈ 1.026 U₁₀',
          source: 'Pierson & Moskowitz 1964; Stewart 2008, eq. 16.31',
        },
      ];
    case 'jonswap':
      return [
        {
          what: 'Spectrum (JONSWAP)',
          formula: 'S = α g² ω⁻⁵ exp(−5/4 (ωp/ω)⁴) γ^r, γ = 3.3; α = 0.076 x̃^−0.22, ωp = 22 (g²/(U₁₀ F))^⅓',
          source: 'Hasselmann et al. 1973, Dtsch. Hydrogr. Z. A8(12)',
        },
        {
          what: 'Hs (JONSWAP)',
          formula: 'g Hs / U₁₀² = 1.6·10⁻³ (g F / U₁₀²)^½',
          source: 'Hasselmann et al. 1973; CERC 1984, Shore Protection Manual, eq. 3-33',
        },
      ];
    case 'phillips':
      return [
        {
          what: 'Spectrum (Phillips)',
          formula: 'S(ω) = α g² ω⁻⁵ above the peak',
          source: 'Phillips 1958, J. Fluid Mech. 4(4); Tessendorf 2001 eq. 23',
        },
      ];
  }
}

/** Measures the sea from `time` on (a few simulated minutes; the clock is not touched). */
export function measurePhysics(measured: MeasuredSea, time: number): PhysicsReport {
  return finish(physicsSteps(measured, time));
}

/** measurePhysics as steps, one simulated time each (the panel spreads them over tasks). */
export function* physicsSteps(measured: MeasuredSea, time: number): Steps<PhysicsReport> {
  const sea = 'swellWavenumber' in measured.sea ? null : measured.sea;
  const depth = sea?.depth ?? Number.POSITIVE_INFINITY;
  const theorySpectrum = sea ? frequencySpectrum(sea) : null;
  // The measurement is sized on the peak: the spectrum's, or the seed's swell's ω = √(g k).
  const peakOmega = theorySpectrum ? theorySpectrum.peak : angularFrequency((measured.sea as { swellWavenumber: number }).swellWavenumber);
  const peakK = theorySpectrum ? (peakOmega * peakOmega) / GRAVITY : (measured.sea as { swellWavenumber: number }).swellWavenumber;
  const tp = (2 * Math.PI) / peakOmega;
  const lambda = (2 * Math.PI) / peakK;

  const theory = (k: number) => angularFrequency(k, depth);
  const points = yield* dispersionSteps(measured.height, {
    size: 4 * lambda,
    resolution: 32,
    startTime: time,
    timeStep: tp / 16,
    snapshots: 16,
    modes: 24,
  });
  const fit = fitDispersion(points, theory);

  const dt = tp / 8;
  const perPoint = yield* heightSeriesSteps(measured.height, probePoints(lambda), time, dt, SERIES_LENGTH);
  const series = new Float64Array(perPoint.length * SERIES_LENGTH);
  perPoint.forEach((s, p) => series.set(s, p * SERIES_LENGTH));
  const welch = meanFrequencySpectrum(perPoint, dt, WELCH_SEGMENT);
  const measuredPeak = spectralPeak(welch);
  // Plotted up to 5 ωp: beyond it the spectra are four decades down.
  const omega: number[] = [];
  const measuredDensity: number[] = [];
  for (let i = 1; i < welch.omega.length && welch.omega[i] <= 5 * peakOmega; i++) {
    omega.push(welch.omega[i]);
    measuredDensity.push(welch.density[i]);
  }

  const citations: Citation[] = [DISPERSION_CITATION, WELCH_CITATION, HS_CITATION, SLOPE_CITATION];
  const notes: string[] = [];
  const resolved = measured.slopeVariance(time);
  const coxMunk = seaSlopeVariance(measured.windSpeed);
  const roughness = measured.seaRoughness ? unresolvedSlopeVariance(coxMunk, resolved) : SUN_DISC_SLOPE_VARIANCE;
  if (!measured.seaRoughness) {
    notes.push('Roughness is off (seaRoughness): the sea is drawn as a mirror but for the sun’s disc, whatever the wind.');
  } else if (resolved > coxMunk) {
    notes.push(
      `The ${measured.name} sea’s own slopes (σ² = ${resolved.toFixed(4)}) exceed Cox & Munk’s for this wind (${coxMunk.toFixed(4)}): its glint gets no roughness but the sun’s disc, and the total sits above the measured sea’s.`,
    );
  }
  let empirical: number | null = null;
  let empiricalName: string | null = null;
  if (sea) {
    citations.push(...spectrumCitation(sea));
    if (sea.spectrum === 'pierson-moskowitz') {
      empirical = piersonMoskowitzHs(sea.windSpeed);
      empiricalName = 'PM 0.21 U₁₉.₅²/g';
    } else if (sea.spectrum === 'jonswap') {
      empirical = jonswapHs(sea.windSpeed, sea.fetch);
      empiricalName = 'JONSWAP (Hasselmann 1973)';
    } else {
      notes.push('Phillips’ spectrum has no empirical growth law for Hs: compare 4σ(η) with 4√m₀ only.');
    }
    if (measured.name === 'gerstner') {
      notes.push(
        'Gerstner: the waves sample 98.9 % of the spectrum’s energy (the band from the 0.1 % to the 99 % quantile), so 4σ(η) sits about 0.6 % below 4√m₀.',
      );
    }
  } else {
    notes.push(
      'The seed’s swell is two fixed sine products whose ω = √(g k) is set from the swell frequency k, so its dispersion points lie on the curve by construction; its Perlin ripples are blended in time, not propagated, and follow no dispersion law. It is drawn from no wind spectrum: there is no theory to compare S(ω), ωp or Hs with.',
    );
  }

  return {
    model: measured.name,
    time,
    dispersion: { points: points.map((p) => ({ ...p, theory: theory(p.k) })), fitRatio: fit.ratio, rmsRelativeError: fit.rmsRelativeError },
    spectrum: { omega, measured: measuredDensity, theory: theorySpectrum ? omega.map((w) => theorySpectrum.density(w)) : null },
    peak: { measured: measuredPeak, theory: theorySpectrum ? theorySpectrum.peak : null },
    peakPeriod: { measured: peakPeriod(measuredPeak), theory: theorySpectrum ? peakPeriod(theorySpectrum.peak) : null },
    hs: {
      measured: significantWaveHeight(series),
      spectral: theorySpectrum ? 4 * Math.sqrt(theorySpectrum.m0) : null,
      empirical,
      empiricalName,
    },
    slopes: { resolved, roughness, total: resolved + roughness, coxMunk, wind: windAtHeight(measured.windSpeed, 12.5) },
    citations,
    notes,
  };
}
