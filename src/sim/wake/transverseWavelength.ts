import { GRAVITY } from './kelvinWake';

/**
 * Wavelength of the wake's transverse waves behind a hull at `speed` m/s: the waves that keep
 * pace with it have phase speed U, and deep water's ω² = g k gives k = g/U², λ = 2πU²/g.
 */
export function transverseWavelength(speed: number, gravity = GRAVITY): number {
  return (2 * Math.PI * speed * speed) / gravity;
}
