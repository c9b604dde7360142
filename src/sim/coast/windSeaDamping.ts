import { MCCOWAN_BREAKER_INDEX } from './waveTransformation';

/** The breaker index γ the swell's field breaks with (McCowan's 0.78), for the wind sea too. */
export const BREAKER_INDEX = MCCOWAN_BREAKER_INDEX;

/**
 * How much of the wind sea the coast keeps at depth `depth` (metres): its waves, up to
 * `windSeaHeight` metres from trough to crest, are limited to γ h, so the whole sea is scaled
 * by min(1, γ h / H) (depth-limited, as the surf zone limits every wave; 0 on land). A
 * stand-in for a spectrum's own depth limit (TMA): every wave of the wind sea is scaled alike.
 */
export function windSeaFactor(depth: number, windSeaHeight: number): number {
  if (windSeaHeight <= 0) return 1;
  return Math.min(1, Math.max(0, (BREAKER_INDEX * depth) / windSeaHeight));
}

/** The wind sea's largest height from trough to crest, metres, from its vertical bound (the largest |η|). */
export function windSeaHeightOf(verticalBound: number): number {
  return 2 * verticalBound;
}
