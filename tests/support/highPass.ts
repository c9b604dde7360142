/**
 * In place: each value of a width × height image less the mean of the (2r + 1)² box around it
 * (clipped at the edges), from a summed-area table. What is left is the pattern finer than the
 * box: the waves' own, without the glint's and the sky's broad gradients.
 */
export function highPass(values: Float64Array, width: number, height: number, r: number): void {
  const stride = width + 1;
  const sums = new Float64Array(stride * (height + 1));
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++)
      sums[(y + 1) * stride + x + 1] = values[y * width + x] + sums[y * stride + x + 1] + sums[(y + 1) * stride + x] - sums[y * stride + x];
  }
  const out = new Float64Array(values.length);
  for (let y = 0; y < height; y++) {
    const y0 = Math.max(0, y - r);
    const y1 = Math.min(height, y + r + 1);
    for (let x = 0; x < width; x++) {
      const x0 = Math.max(0, x - r);
      const x1 = Math.min(width, x + r + 1);
      const sum = sums[y1 * stride + x1] - sums[y0 * stride + x1] - sums[y1 * stride + x0] + sums[y0 * stride + x0];
      out[y * width + x] = values[y * width + x] - sum / ((x1 - x0) * (y1 - y0));
    }
  }
  values.set(out);
}
