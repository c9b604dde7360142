/**
 * Widest blur the underwater passes run, texels on each side. The blur runs at half
 * resolution (src/render/underwaterPost.ts), where σ = 8 screen pixels, the parameter's top,
 * is halfResolutionSigma(8) ≈ 3.97 texels, and 3σ rounds up to 12.
 */
export const BLUR_MAX_RADIUS = 12;
/**
 * Taps of the linear-sampled kernel at BLUR_MAX_RADIUS: the centre and ⌈12 / 2⌉ = 6 pairs,
 * with one to spare. Also the GLSL array size and loop bound (BLUR_MAX_TAPS, from
 * `#include <oceano_constants>`).
 */
export const BLUR_MAX_TAPS = 8;

/**
 * The σ of the half-resolution Gaussian, in half-resolution texels, that gives a blur of σ
 * screen pixels overall. Reading the image at half resolution averages 2×2 pixels (a box
 * 2 px wide, variance 2²/12 px²) and the bilinear upsample is a tent 2 px to each side
 * (variance 2²/6 px²); variances of successive filters add, so the Gaussian supplies the
 * rest, σ² − 1 px², and below σ = 1 px the resampling alone is already that soft.
 */
export function halfResolutionSigma(sigma: number): number {
  return Math.sqrt(Math.max(sigma * sigma - 1, 0)) / 2;
}

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

/** A Gaussian kernel folded for bilinear texture taps; see linearSampledKernel. */
export interface LinearSampledKernel {
  /** offsets[0] = 0 (the centre tap); offsets[k] is the distance of the k-th pair of taps, in texels. */
  offsets: Float32Array;
  /** weights[0] for the centre; weights[k] for each tap of the k-th pair (one on each side). */
  weights: Float32Array;
  /** Taps used: the centre and taps − 1 pairs. */
  taps: number;
}

/**
 * The same normalised Gaussian with about half the texture reads: two neighbouring texels i
 * and i + 1 on one side are read as one bilinear tap at (i w_i + (i+1) w_{i+1}) / (w_i + w_{i+1})
 * with weight w_i + w_{i+1}, since linear filtering there returns exactly
 * (w_i t_i + w_{i+1} t_{i+1}) / (w_i + w_{i+1}). Filtering is linear in the texel values, so
 * the sum equals the discrete convolution for any signal (Rákos, "Efficient Gaussian blur
 * with linear sampling", 2010). A tail texel with no partner is read alone. `maxTaps` bounds
 * the arrays (the shader's loop length).
 */
export function linearSampledKernel(sigma: number, maxRadius: number, maxTaps: number): LinearSampledKernel {
  const discrete = gaussianKernel(sigma, maxRadius);
  const radius = sigma === 0 ? 0 : Math.min(maxRadius, Math.ceil(3 * sigma));
  const offsets = new Float32Array(maxTaps);
  const weights = new Float32Array(maxTaps);
  weights[0] = discrete[0];
  let taps = 1;
  for (let i = 1; i <= radius; i += 2) {
    if (taps >= maxTaps) throw new RangeError(`σ = ${sigma} needs more than ${maxTaps} linear taps.`);
    const a = discrete[i];
    const b = i + 1 <= radius ? discrete[i + 1] : 0;
    weights[taps] = a + b;
    offsets[taps] = (i * a + (i + 1) * b) / (a + b);
    taps++;
  }
  return { offsets, weights, taps };
}
