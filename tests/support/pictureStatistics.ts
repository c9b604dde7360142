import { PNG } from 'pngjs';
import { highFrequencyEnergy } from './imageEnergy';
import { pixelLuminance } from './luminance';

/**
 * Luminance statistics (0–255) of a picture's rows from `fromRow` (a share of the height) down:
 * the sea below the horizon. `detail` is the mean absolute step from a pixel to the mean of its
 * four neighbours, `energy` the mean squared Laplacian (imageEnergy.ts): both fall when the sea
 * loses its fine detail.
 */
export function seaStatistics(png: Buffer, fromRow: number): { mean: number; std: number; detail: number; energy: number } {
  const { width, height, data } = PNG.sync.read(png);
  const top = Math.ceil(height * fromRow);
  const rows = height - top;
  const lum = (x: number, y: number) => pixelLuminance(data, y * width + x);
  let sum = 0;
  let squares = 0;
  for (let i = top * width; i < height * width; i++) {
    const l = pixelLuminance(data, i);
    sum += l;
    squares += l * l;
  }
  let detail = 0;
  let inner = 0;
  for (let y = Math.max(top, 1); y < height - 1; y++) {
    for (let x = 1; x < width - 1; x++, inner++) {
      detail += Math.abs(lum(x, y) - (lum(x - 1, y) + lum(x + 1, y) + lum(x, y - 1) + lum(x, y + 1)) / 4);
    }
  }
  const n = rows * width;
  const mean = sum / n;
  const energy = highFrequencyEnergy(data.subarray(top * width * 4), width, rows);
  return { mean, std: Math.sqrt(squares / n - mean * mean), detail: detail / inner, energy };
}

/** Pixels in columns [x0, x1) whose colour differs by more than `levels` (0–255) in any channel. */
export function differingPixels(a: PNG, b: PNG, x0: number, x1: number, levels = 0): number {
  let count = 0;
  for (let y = 0; y < a.height; y++) {
    for (let x = x0; x < x1; x++) {
      const i = (y * a.width + x) * 4;
      if (
        Math.max(Math.abs(a.data[i] - b.data[i]), Math.abs(a.data[i + 1] - b.data[i + 1]), Math.abs(a.data[i + 2] - b.data[i + 2])) > levels
      )
        count++;
    }
  }
  return count;
}
