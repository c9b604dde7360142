import { groupVelocity, waveNumber } from '../waves/dispersion';
import { MCCOWAN_BREAKER_INDEX } from './waveTransformation';

/**
 * The physics the coast's field is built with: the dispersion relation (k from ω and h, and
 * the group velocity) and the breaker index γ. The field uses linear theory; the tests build
 * fields with a planted wrong model (deep-water dispersion, a wrong γ) to show that their
 * checks catch it.
 */
export interface CoastWaveModel {
  /** k (rad/m) of angular frequency ω (rad/s) over depth h (m). */
  waveNumber: (omega: number, depth: number) => number;
  /** c_g = dω/dk (m/s) of wavenumber k over depth h. */
  groupVelocity: (k: number, depth: number) => number;
  /** γ: waves break where H > γ h. */
  breakerIndex: number;
}

/** Airy's linear theory, ω² = g k tanh(k h), with McCowan's γ = 0.78. */
export const LINEAR_THEORY: CoastWaveModel = { waveNumber, groupVelocity, breakerIndex: MCCOWAN_BREAKER_INDEX };

/**
 * Below this depth (m) the wavenumber is frozen at its value here: k ∝ 1/√h grows without
 * bound at the shoreline, and the waves there are already broken down to H = γ h ≤ 8 cm.
 */
export const SHALLOWEST_DEPTH = 0.1;

/** The wavenumber the field uses at depth h: k(max(h, SHALLOWEST_DEPTH)), on land too, so the phase stays smooth there. */
export function fieldWaveNumber(model: CoastWaveModel, omega: number, depth: number): number {
  return model.waveNumber(omega, Math.max(depth, SHALLOWEST_DEPTH));
}
