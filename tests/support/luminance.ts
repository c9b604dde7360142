import { PNG } from 'pngjs';

/** Luminance from red, green and blue by Rec. 709's weights, in the inputs' own scale. */
export function rgbLuminance(r: number, g: number, b: number): number {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

/** Luminance (Rec. 709 weights on the stored sRGB levels, 0–255) of pixel `i` of RGBA bytes. */
export function pixelLuminance(rgba: ArrayLike<number>, i: number): number {
  return rgbLuminance(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
}

/** Each pixel's luminance (Rec. 709 weights on the stored sRGB levels, 0–255), row by row. */
export function pngLuminances(png: Buffer): Float64Array {
  const image = PNG.sync.read(png);
  const values = new Float64Array(image.width * image.height);
  for (let i = 0; i < values.length; i++) values[i] = pixelLuminance(image.data, i);
  return values;
}
