// The blur's limits on their own, so the shaders' constants need not bring the kernel code with them.
/**
 * Widest blur the underwater passes run, texels on each side. The blur runs at half
 * resolution (src/render/underwater/underwaterPost.ts), where σ = 8 screen pixels, the parameter's top,
 * is halfResolutionSigma(8) ≈ 3.97 texels, and 3σ rounds up to 12.
 */
export const BLUR_MAX_RADIUS = 12;
/**
 * Taps of the linear-sampled kernel at BLUR_MAX_RADIUS: the centre and ⌈12 / 2⌉ = 6 pairs,
 * with one to spare. Also the GLSL array size and loop bound (BLUR_MAX_TAPS, from
 * `#include <oceano_constants>`).
 */
export const BLUR_MAX_TAPS = 8;
