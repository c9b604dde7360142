import type { GerstnerWave } from './gerstnerWaves';

/**
 * The mean-square slope of one trochoid over the sea's area. A wave of amplitude A, wavenumber
 * k and horizontal amplitude QA draws X = p − QA sin θ, Y = A cos θ (θ = kp), whose slope is
 * dY/dX = −Ak sin θ / (1 − q cos θ), q = QAk. Weighted by the area each grid step covers,
 * dX = (1 − q cos θ) dp (which averages to dp):
 *   ⟨s²⟩ = (Ak)² (1/2π) ∫ sin²θ / (1 − q cos θ) dθ = (Ak)² (1 − √(1 − q²)) / q²
 * (the integral by the residue theorem). q → 0 gives the sine wave's (Ak)²/2; the cusp q = 1
 * gives (Ak)², finite though the slope at the cusp is not.
 */
export function trochoidSlopeVariance(amplitude: number, wavenumber: number, horizontal: number): number {
  const slope = amplitude * wavenumber;
  const q = Math.min(1, horizontal * wavenumber);
  // Below q ≈ 1e-4 the closed form loses its digits to cancellation; its series is 1/2 + q²/8.
  const shape = q < 1e-4 ? 0.5 + (q * q) / 8 : (1 - Math.sqrt(1 - q * q)) / (q * q);
  return slope * slope * shape;
}

/** A wave's wavenumber, rad/m, from its wavevector in cycles per metre. */
export function gerstnerWavenumber(wave: GerstnerWave): number {
  return 2 * Math.PI * Math.hypot(wave.cx, wave.cz);
}

/** The sum over the waves: different wavevectors, uncorrelated slopes (interactions between trochoids left out). */
export function gerstnerSlopeVariance(waves: readonly GerstnerWave[]): number {
  let sum = 0;
  for (const wave of waves) sum += trochoidSlopeVariance(wave.amplitude, gerstnerWavenumber(wave), wave.horizontal);
  return sum;
}
