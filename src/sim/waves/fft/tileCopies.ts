/**
 * Far away, the two shorter FFT tiles are each read twice, a fraction of a tile apart, and the
 * two readings blended (shaders/waves/fft.glsl fftBlendCopies), so that no tile's period shows
 * from high above. The blend is a rotation: own · cos θ + copy · sin θ. Two independent
 * Gaussian fields so combined make a Gaussian field with the same spectrum for any θ, since the
 * weights' squares add to one (Heitz & Neyret 2018, "High-performance by-example noise using
 * a histogram-preserving blending operator"); a negative weight only turns crests into troughs,
 * which a Gaussian sea cannot tell apart.
 *
 * θ comes from a field that never repeats (breakupOther): θ = far · TILE_COPY_TURN · field.
 * One tile away the field has changed, so the repeat left in the blend is
 * E[cos θ]² + E[sin θ]² (tileCopyRepeat). Non-negative weights, one copy or the other, leave at
 * least half of it; a turn fast enough that cos θ and sin θ average to zero over the field
 * leaves none. TILE_COPY_TURN, in radians per unit of the field, lies just past the first turn
 * at which E[cos θ] passes through zero (6.8 for this field, whose spread is 0.34); a faster
 * turn would blend over shorter distances, smearing the copies' longer waves.
 */
export const TILE_COPY_TURN = 7;

/** The weights of a tile's own reading and its copy, at a pixel `far` (0 near, 1 far) where the field is `field`. */
export function tileCopyWeights(field: number, far: number): [own: number, copy: number] {
  const angle = far * TILE_COPY_TURN * field;
  return [Math.cos(angle), Math.sin(angle)];
}

/**
 * The share of a tile's repeat left in the blend: the correlation between a pixel's weights
 * and those one tile away, Σ E[w(x) w(x + tile)], for pairs of the field's values sampled that far apart.
 */
export function tileCopyRepeat(pairs: readonly [number, number][], weights: (field: number) => [number, number]): number {
  let sum = 0;
  for (const [here, tileAway] of pairs) {
    const [ownHere, copyHere] = weights(here);
    const [ownAway, copyAway] = weights(tileAway);
    sum += ownHere * ownAway + copyHere * copyAway;
  }
  return sum / pairs.length;
}
