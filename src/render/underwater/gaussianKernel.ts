import { BLUR_MAX_RADIUS, BLUR_MAX_TAPS } from './blurLimits';

export { BLUR_MAX_RADIUS, BLUR_MAX_TAPS };

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

/**
 * The largest share of a kernel's mass on one side past 1 texel that the one-pass blur below
 * may leave out. Left out, the ring past 1 texel (about four such shares) goes back to the
 * 3×3 centre, so a pixel moves by at most 4/512 of the contrast around it: 2 levels next to a
 * black-to-white edge, nothing in the water's smooth gradients (tests/unit/render/underwater/onePassBlur.test.ts).
 */
export const ONE_PASS_TAIL = 1 / 512;

/**
 * A Gaussian that hardly reaches past 1 texel, the default underwater blur's (σ = 1.5 px on
 * screen, 0.56 texels at half resolution), in one pass of four bilinear taps instead of two
 * separable passes: a tap at offset o between texels 0 and 1 reads (1 − o) t₀ + o t₁, so the
 * mean of the taps at ±o is (1 − o) t₀ + (o / 2)(t₋₁ + t₁), the kernel [a, b, a] (normalised
 * over 1 texel) when o = 2a / (b + 2a); the four taps at (±o, ±o) read its product in x and y,
 * the same 3×3 kernel the two passes convolve. Returns o, or null when more than ONE_PASS_TAIL
 * of the kernel lies past 1 texel on a side (then the two passes run).
 */
export function onePassBlurOffset(sigma: number): number | null {
  const kernel = gaussianKernel(sigma, 2);
  if (kernel[2] > ONE_PASS_TAIL) return null;
  const a = kernel[1];
  const b = kernel[0];
  return (2 * a) / (b + 2 * a);
}
