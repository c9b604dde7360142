/**
 * Cascades: several FFT tiles of different sizes summed, so that the sea has both the long
 * swell of the spectral peak and centimetre ripples without one huge grid, and so that no
 * tile's repeat is visible (their sizes are not multiples of one another). Each tile keeps
 * only the wavenumbers of its own radial band [kMin, kMax): the bands touch and do not
 * overlap, so no wave is counted twice. (The idea: Gamper, "Ocean surface generation and
 * rendering", 2018; gasgiant/FFT-Ocean, 2021. Sizes and cuts here are our own.)
 */
export interface Cascade {
  /** Tile side, m. */
  size: number;
  /** Lower edge of this tile's band of |k|, rad/m (0 for the largest tile). */
  kMin: number;
  /** Upper edge (exclusive) of the band, rad/m; Infinity for the smallest tile (up to its grid's Nyquist). */
  kMax: number;
}

/** The largest tile holds this many peak wavelengths: the peak sits at |k| = 8 Δk, well inside, for every wind. */
export const PEAK_WAVELENGTHS_PER_TILE = 8;
/**
 * Size ratios between successive tiles, chosen far from simple fractions so their repeats do
 * not line up: for every pair of tiles, q tiles of one (q ≤ 8) miss a whole number of the other
 * by at least 0.08 of a tile. (4.37 for the second ratio put 3 of the largest tiles within 0.01
 * of 62 of the smallest: a joint repeat 3 L₀ away, 2 km at 10 m/s, seen from high above.)
 */
export const TILE_RATIOS = [4.73, 4.46] as const;

/**
 * Tiles for a sea whose spectral peak has wavelength `peakWavelength` (m), each an n × n FFT.
 * The cut between tile i and the next lies at half tile i's Nyquist, n/4 · 2π/Lᵢ, so that
 * every wave a tile carries has at least 4 grid points per wavelength (bilinear sampling
 * of shorter ones would flatten them).
 */
export function cascadeLayout(peakWavelength: number, n: number): Cascade[] {
  const sizes = [PEAK_WAVELENGTHS_PER_TILE * peakWavelength];
  for (const r of TILE_RATIOS) sizes.push(sizes[sizes.length - 1] / r);
  return sizes.map((size, i) => ({
    size,
    kMin: i === 0 ? 0 : bandEdge(sizes[i - 1], n),
    kMax: i === sizes.length - 1 ? Number.POSITIVE_INFINITY : bandEdge(size, n),
  }));
}

function bandEdge(size: number, n: number): number {
  return (n / 4) * ((2 * Math.PI) / size);
}

/** Whether a wavenumber of magnitude k belongs to this cascade. */
export function inBand(cascade: Cascade, k: number): boolean {
  return k >= cascade.kMin && k < cascade.kMax;
}
