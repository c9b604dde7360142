/**
 * Which mip level of a sky cube a rough mirror reads (the CPU twin of shaders/skyCube.glsl
 * skyCubeColorRough). Facets of mean-square slope σ² (both axes) tilt by √(σ²/2) per axis and
 * turn the reflected ray by twice that, √(2σ²) radians; a box of w texels spreads a ray as far
 * as w/√12 of them, and a face of `faceSize` texels spans π/2. So the box is
 * w = faceSize √(24 σ²) / (π/2) = faceSize √(9.73 σ²) texels wide: mip level log2 w.
 */
export function skyBlurLevel(faceSize: number, slopeVariance: number): number {
  return Math.max(Math.log2(faceSize * Math.sqrt(9.73 * slopeVariance)), 0);
}

/** The mean-square slope whose blur reads mip level `level` (> 0) of a sky of `faceSize` texels: skyBlurLevel's inverse. */
export function slopeVarianceAtLevel(faceSize: number, level: number): number {
  return (2 ** level / faceSize) ** 2 / 9.73;
}

/**
 * The face size of a cube that holds the sky as that rough mirror shows it, finely enough to be
 * read with one bilinear lookup: the blend's texels would otherwise be filtered twice, which
 * shows where the sky changes fast (the horizon under a low sun). PREFILTER_OVERSAMPLING times
 * the resolution of the finer of the two levels blended, at least MIN_PREFILTERED_SIZE texels
 * and at most the sky's own.
 */
export const PREFILTER_OVERSAMPLING = 8;
export const MIN_PREFILTERED_SIZE = 32;

export function prefilteredFaceSize(faceSize: number, slopeVariance: number): number {
  const finer = Math.floor(skyBlurLevel(faceSize, slopeVariance));
  return Math.min(faceSize, Math.max(MIN_PREFILTERED_SIZE, (PREFILTER_OVERSAMPLING * faceSize) / 2 ** finer));
}
