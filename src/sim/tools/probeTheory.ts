import type { OceanParams } from '../params/params';
import { deepWaterAngularFrequency, surfaceStateAt, swellHeight } from '../waves/seed/seedSurface';
import { frequencySpectrum, type FrequencySpectrum } from '../waves/spectra/waveSpectrum';
import { seaStateFromParams } from '../waves/spectra/seaState';
import { crestToTrough, meanUpCrossingPeriod, type HeightRecord } from './probeStatistics';

/**
 * What the wave model says the probe should measure, in the probe's own terms (a period and
 * a height), so the two can stand side by side.
 *
 * The seed's swell is a closed form, not a random sea: η = A [sin(kx + ωt) cos(kz + 0.7ωt) + …]
 * with ω = √(g k). At a fixed point a product of a sine and a cosine is the sum of two waves,
 * ½ sin(kx + kz + 1.7ωt) + ½ sin(kx − kz + 0.3ωt), and the second, smaller product adds two
 * more, so the water there does not rise and fall once every 2π/ω. Its theory is therefore the
 * swell's formula itself, evaluated at the same point and times as the record, measured the
 * same way; 2π/ω is given beside it as the period the formula is built from.
 *
 * A spectral sea (fft, gerstner) is a Gaussian random sea with spectrum S(ω). Its mean zero
 * up-crossing period is Tz = 2π √(m₀/m₂) (Rice 1944, "Mathematical analysis of random noise",
 * Bell Syst. Tech. J. 23, §3.3; Holthuijsen 2007, eq. 4.2.11), its significant height
 * Hs = 4√m₀, with mₙ = ∫ ωⁿ S(ω) dω; its peak period Tp = 2π/ωp is given beside them.
 */
export type ProbeTheory =
  | {
      kind: 'swell';
      /** Tz of the swell's formula over the record's times, s (NaN with under two up-crossings). */
      period: number;
      /** Its crest-to-trough height over those times, m. */
      height: number;
      /** 2π/ω, ω = √(g k) the swell's angular frequency, s. */
      swellPeriod: number;
    }
  | {
      kind: 'spectrum';
      /** Tz = 2π √(m₀/m₂), s. */
      period: number;
      /** Hs = 4 √m₀, m. */
      height: number;
      /** Tp = 2π/ωp, s. */
      peakPeriod: number;
    };

const TWO_PI = 2 * Math.PI;
/** The moments are integrated from ωp/RANGE to ωp·RANGE: S falls as ω⁻⁵ above, and as e^{−(ωp/ω)⁴} below, the peak. */
const RANGE = 200;
const POINTS = 6000;

/** mₙ = ∫ ωⁿ S(ω) dω, by the trapezoid rule on a logarithmic grid around the peak (∫ f dω = ∫ f ω d(ln ω)). */
export function spectralMoment(spectrum: Pick<FrequencySpectrum, 'density' | 'peak'>, n: number): number {
  const lo = Math.log(spectrum.peak / RANGE);
  const hi = Math.log(spectrum.peak * RANGE);
  const step = (hi - lo) / POINTS;
  let sum = 0;
  for (let i = 0; i <= POINTS; i++) {
    const omega = Math.exp(lo + i * step);
    const f = omega ** (n + 1) * spectrum.density(omega);
    sum += i === 0 || i === POINTS ? f / 2 : f;
  }
  return sum * step;
}

/** Tz, Hs and Tp of a sea drawn from `spectrum`. */
export function spectralTheory(spectrum: Pick<FrequencySpectrum, 'density' | 'peak'>): ProbeTheory {
  const m0 = spectralMoment(spectrum, 0);
  const m2 = spectralMoment(spectrum, 2);
  return { kind: 'spectrum', period: TWO_PI * Math.sqrt(m0 / m2), height: 4 * Math.sqrt(m0), peakPeriod: TWO_PI / spectrum.peak };
}

/** The seed swell's own heights at (x, z) and the record's times. */
export function swellRecord(
  params: Pick<OceanParams, 'swellAmplitude' | 'swellFrequency' | 'rippleStrength' | 'rippleBlendSpeed'>,
  x: number,
  z: number,
  times: ArrayLike<number>,
): HeightRecord {
  const heights = Float64Array.from(times, (t) => swellHeight(surfaceStateAt(params, t), x, z));
  return { times, heights };
}

/** The theory for the probe at (x, z) whose record was taken at `times`, for the wave model the parameters choose. */
export function probeTheory(params: OceanParams, x: number, z: number, times: ArrayLike<number>): ProbeTheory {
  if (params.waves !== 'seed') return spectralTheory(frequencySpectrum(seaStateFromParams(params)));
  const swell = swellRecord(params, x, z, times);
  return {
    kind: 'swell',
    period: meanUpCrossingPeriod(swell),
    height: crestToTrough(swell),
    swellPeriod: TWO_PI / deepWaterAngularFrequency(params.swellFrequency),
  };
}
