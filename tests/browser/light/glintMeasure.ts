import { PNG } from 'pngjs';
import { pixelLuminance } from '../../support/luminance';

/**
 * The glint's horizontal width, px: in each row of [top, bottom) the pixels brighter than
 * halfway from the row's 10th percentile of luminance (the sea beside the glint) to its
 * brightest, counted and averaged over the rows. A full width at half maximum, so a glint
 * that is wider but dimmer (a rougher sea) reads as wider.
 */
export function glintWidth(png: Buffer, top: number, bottom: number): number {
  const image = PNG.sync.read(png);
  const { width } = image;
  const row = new Float64Array(width);
  let pixels = 0;
  let rows = 0;
  for (let y = Math.max(0, top); y < Math.min(bottom, image.height); y++) {
    for (let x = 0; x < width; x++) row[x] = pixelLuminance(image.data, y * width + x);
    const sorted = Float64Array.from(row).sort();
    const half = (sorted[Math.floor(0.1 * width)] + sorted[width - 1]) / 2;
    for (let x = 0; x < width; x++) if (row[x] > half) pixels++;
    rows++;
  }
  return rows === 0 ? 0 : pixels / rows;
}

/** Mean absolute luminance change, 0–255, between two frames over the rows [top, bottom). */
export function meanChange(a: Buffer, b: Buffer, top: number, bottom: number): number {
  const imageA = PNG.sync.read(a);
  const imageB = PNG.sync.read(b);
  const { width } = imageA;
  let sum = 0;
  let count = 0;
  for (let y = Math.max(0, top); y < Math.min(bottom, imageA.height); y++) {
    for (let x = 0; x < width; x++) {
      const i = y * width + x;
      sum += Math.abs(pixelLuminance(imageA.data, i) - pixelLuminance(imageB.data, i));
      count++;
    }
  }
  return count === 0 ? 0 : sum / count;
}
