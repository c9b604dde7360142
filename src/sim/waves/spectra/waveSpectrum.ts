import { angularFrequency, groupVelocity, waveNumber } from '../dispersion';
import { spreadingFunction } from './directionalSpreading';
import { jonswapM0Approx, jonswapShape, jonswapWithShape } from './jonswap';
import { piersonMoskowitz, piersonMoskowitzM0, piersonMoskowitzPeak } from './piersonMoskowitz';
import { phillips, phillipsM0, phillipsPeak } from './phillips';
import { windVector, type SeaState } from './seaState';

/** A one-sided frequency spectrum S(ω) (m²·s/rad) with its peak ωp and its variance m₀ (m²). */
export interface FrequencySpectrum {
  density(omega: number): number;
  peak: number;
  /** m₀ = ∫S dω; exact for PM and Phillips, the DNV approximation for JONSWAP. */
  m0: number;
}

export function frequencySpectrum(sea: SeaState): FrequencySpectrum {
  const u = sea.windSpeed;
  switch (sea.spectrum) {
    case 'pierson-moskowitz':
      return { density: (w) => piersonMoskowitz(w, u), peak: piersonMoskowitzPeak(u), m0: piersonMoskowitzM0(u) };
    case 'phillips':
      return { density: (w) => phillips(w, u), peak: phillipsPeak(u), m0: phillipsM0(u) };
    case 'jonswap': {
      const { alpha, peak } = jonswapShape(u, sea.fetch);
      return { density: (w) => jonswapWithShape(w, alpha, peak), peak, m0: jonswapM0Approx(alpha, peak) };
    }
  }
}

/** Wavelength (m) of the spectral peak, through the dispersion relation at the sea's depth. */
export function peakWavelength(sea: SeaState): number {
  return (2 * Math.PI) / waveNumber(frequencySpectrum(sea).peak, sea.depth);
}

/**
 * The directional wavenumber spectrum F(kx, kz) (m⁴: m² of variance per (rad/m)²), so that
 * ∫∫F dkx dkz = m₀. From S(ω): S(k) = S(ω(k)) dω/dk (energy conserved across the change of
 * variable), spread over directions by D(θ) with ∫D dθ = 1, and dkx dkz = k dk dθ gives the 1/k.
 * (Tessendorf 2001 §3.3; Horvath, "Empirical directional wave spectra for computer graphics",
 * DigiPro 2015, eq. 17–20.)
 */
export function directionalSpectrum(sea: SeaState, spectrum: FrequencySpectrum): (kx: number, kz: number) => number {
  const [wx, wz] = windVector(sea.windDirection);
  const windAngle = Math.atan2(wz, wx);
  const spreading = spreadingFunction(sea.spreadingModel, sea.spreading, spectrum.peak, sea.windSpeed);
  return (kx, kz) => {
    const k = Math.hypot(kx, kz);
    if (k === 0) return 0;
    const omega = angularFrequency(k, sea.depth);
    const theta = Math.atan2(kz, kx) - windAngle;
    return (spectrum.density(omega) * groupVelocity(k, sea.depth) * spreading(theta, omega)) / k;
  };
}
