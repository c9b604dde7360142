import FFT from 'fft.js';

/**
 * The normalised autocorrelation of an image's values, for every lag (dx, dy) with |dx| < width/2
 * and |dy| < height/2: ρ(d) = Σ (a(p) − μ)(a(p + d) − μ) / (N(d) σ²), where N(d) is the number of
 * pixel pairs that lag has inside the image. A pattern that repeats every P pixels has ρ ≈ 1
 * at d = P; an image whose pieces are independent has ρ ≈ 0 away from d = 0.
 * Computed through the FFT of the image zero-padded to twice its size, so the lags do not wrap.
 */
export interface Autocorrelation {
  /** Lags run from −maxX to maxX and −maxY to maxY. */
  maxX: number;
  maxY: number;
  /** ρ at (dx, dy), row-major from (−maxX, −maxY). */
  at(dx: number, dy: number): number;
}

function nextPowerOfTwo(n: number): number {
  let p = 4;
  while (p < n) p *= 2;
  return p;
}

/** In place: the 2-D FFT (inverse = true: unnormalised inverse) of a complex rows × cols array, interleaved re, im. */
function fft2d(data: Float64Array, rows: number, cols: number, inverse: boolean): void {
  const rowFft = new FFT(cols);
  const colFft = new FFT(rows);
  const rowIn = rowFft.createComplexArray() as number[];
  const rowOut = rowFft.createComplexArray() as number[];
  for (let r = 0; r < rows; r++) {
    for (let i = 0; i < 2 * cols; i++) rowIn[i] = data[2 * r * cols + i];
    if (inverse) rowFft.inverseTransform(rowOut, rowIn);
    else rowFft.transform(rowOut, rowIn);
    for (let i = 0; i < 2 * cols; i++) data[2 * r * cols + i] = rowOut[i];
  }
  const colIn = colFft.createComplexArray() as number[];
  const colOut = colFft.createComplexArray() as number[];
  for (let c = 0; c < cols; c++) {
    for (let r = 0; r < rows; r++) {
      colIn[2 * r] = data[2 * (r * cols + c)];
      colIn[2 * r + 1] = data[2 * (r * cols + c) + 1];
    }
    if (inverse) colFft.inverseTransform(colOut, colIn);
    else colFft.transform(colOut, colIn);
    for (let r = 0; r < rows; r++) {
      data[2 * (r * cols + c)] = colOut[2 * r];
      data[2 * (r * cols + c) + 1] = colOut[2 * r + 1];
    }
  }
}

export function autocorrelation(values: ArrayLike<number>, width: number, height: number): Autocorrelation {
  if (values.length !== width * height) throw new RangeError(`Expected ${width * height} values, got ${values.length}.`);
  let mean = 0;
  for (let i = 0; i < values.length; i++) mean += values[i];
  mean /= values.length;
  let variance = 0;
  for (let i = 0; i < values.length; i++) variance += (values[i] - mean) ** 2;
  variance /= values.length;
  const cols = nextPowerOfTwo(2 * width);
  const rows = nextPowerOfTwo(2 * height);
  const data = new Float64Array(2 * rows * cols);
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) data[2 * (y * cols + x)] = values[y * width + x] - mean;
  fft2d(data, rows, cols, false);
  for (let i = 0; i < rows * cols; i++) {
    data[2 * i] = data[2 * i] ** 2 + data[2 * i + 1] ** 2;
    data[2 * i + 1] = 0;
  }
  fft2d(data, rows, cols, true);
  // fft.js's inverse is already divided by its size, once per axis.
  const maxX = Math.floor((width - 1) / 2);
  const maxY = Math.floor((height - 1) / 2);
  const spanX = 2 * maxX + 1;
  const rho = new Float64Array(spanX * (2 * maxY + 1));
  for (let dy = -maxY; dy <= maxY; dy++) {
    for (let dx = -maxX; dx <= maxX; dx++) {
      const r = (dy + rows) % rows;
      const c = (dx + cols) % cols;
      const pairs = (width - Math.abs(dx)) * (height - Math.abs(dy));
      rho[(dy + maxY) * spanX + dx + maxX] = variance === 0 ? 0 : data[2 * (r * cols + c)] / (pairs * variance);
    }
  }
  return {
    maxX,
    maxY,
    at: (dx, dy) => rho[(dy + maxY) * spanX + dx + maxX],
  };
}

/**
 * The highest autocorrelation at lags longer than `minLag` pixels, after averaging ρ over
 * each lag's (2·smooth + 1)² neighbourhood: a repeat shows as a bump as wide as the repeated
 * feature, while the scatter of a finite image is as fine as a pixel and averages away.
 * Returns the peak and where it is.
 */
export function peakBeyond(acf: Autocorrelation, minLag: number, smooth = 1): { rho: number; dx: number; dy: number } {
  let best = { rho: Number.NEGATIVE_INFINITY, dx: 0, dy: 0 };
  const rx = acf.maxX - smooth;
  const ry = acf.maxY - smooth;
  for (let dy = -ry; dy <= ry; dy++) {
    // ρ(−d) = ρ(d): half the lags are enough.
    for (let dx = dy === 0 ? 0 : -rx; dx <= rx; dx++) {
      if (dy < 0) continue;
      if (Math.hypot(dx, dy) <= minLag) continue;
      let sum = 0;
      for (let j = -smooth; j <= smooth; j++) for (let i = -smooth; i <= smooth; i++) sum += acf.at(dx + i, dy + j);
      const rho = sum / (2 * smooth + 1) ** 2;
      if (rho > best.rho) best = { rho, dx, dy };
    }
  }
  return best;
}
