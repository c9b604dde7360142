/** Widest blur the underwater passes run, taps on each side: also the GLSL array size (BLUR_MAX_RADIUS). */
export const BLUR_MAX_RADIUS = 24;

/**
 * One side of a normalised 1D Gaussian kernel: weights[0] is the centre tap, weights[i]
 * the tap i pixels away on each side. The radius is 3σ rounded up (99.7 % of the mass),
 * capped at maxRadius; the kept taps are renormalised so the blur never darkens.
 */
export function gaussianKernel(sigma: number, maxRadius: number): Float32Array {
  if (!Number.isFinite(sigma) || sigma < 0) throw new RangeError(`gaussianKernel needs σ ≥ 0, got ${sigma}.`);
  const weights = new Float32Array(maxRadius + 1);
  if (sigma === 0) {
    weights[0] = 1;
    return weights;
  }
  const radius = Math.min(maxRadius, Math.ceil(3 * sigma));
  let total = 0;
  for (let i = 0; i <= radius; i++) {
    const w = Math.exp(-(i * i) / (2 * sigma * sigma));
    weights[i] = w;
    total += i === 0 ? w : 2 * w;
  }
  for (let i = 0; i <= radius; i++) weights[i] /= total;
  return weights;
}
