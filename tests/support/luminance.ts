import { PNG } from 'pngjs';

/** Each pixel's luminance (Rec. 709 weights on the stored sRGB levels, 0–255), row by row. */
export function pngLuminances(png: Buffer): Float64Array {
  const image = PNG.sync.read(png);
  const values = new Float64Array(image.width * image.height);
  for (let i = 0; i < values.length; i++) values[i] = 0.2126 * image.data[4 * i] + 0.7152 * image.data[4 * i + 1] + 0.0722 * image.data[4 * i + 2];
  return values;
}
