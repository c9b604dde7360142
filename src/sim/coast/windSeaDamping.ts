/**
 * The breaker index γ: a wave breaks once its height passes γ times the depth (McCowan 1894's
 * solitary wave, 0.78; Battjes & Janssen 1978 observe 0.5–1.0).
 */
export const BREAKER_INDEX = 0.78;

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
