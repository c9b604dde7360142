import { pixelLuminance } from './luminance';

/**
 * High-frequency energy of an RGBA image: the mean squared discrete Laplacian of its
 * luminance over the interior pixels. A blur removes fine detail, so it lowers this
 * number; a flat or linear-gradient image has none. Luminance uses Rec. 709 weights on
 * the stored (0–255) values.
 */
export function highFrequencyEnergy(rgba: Uint8Array | Uint8ClampedArray | Buffer, width: number, height: number): number {
  if (rgba.length !== width * height * 4) throw new RangeError(`Expected ${width * height * 4} RGBA bytes, got ${rgba.length}.`);
  if (width < 3 || height < 3) return 0;
  const luma = new Float64Array(width * height);
  for (let i = 0; i < width * height; i++) {
    luma[i] = pixelLuminance(rgba, i);
  }
  let sum = 0;
  for (let y = 1; y < height - 1; y++) {
    for (let x = 1; x < width - 1; x++) {
      const i = y * width + x;
      const laplacian = luma[i - 1] + luma[i + 1] + luma[i - width] + luma[i + width] - 4 * luma[i];
      sum += laplacian * laplacian;
    }
  }
  return sum / ((width - 2) * (height - 2));
}
