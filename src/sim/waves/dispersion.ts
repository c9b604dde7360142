/**
 * Dispersion of surface gravity waves: how fast a wave of wavenumber k (rad/m) oscillates.
 * Linear (Airy) wave theory gives ω² = g k tanh(k h) for water of depth h, which tends to the
 * deep-water ω² = g k when k h ≫ 1 (tanh(3) ≈ 0.995). Source: Tessendorf, "Simulating Ocean
 * Water" (SIGGRAPH course notes 2001), §3.2, eq. (14) and (15); Kinsman, "Wind Waves" (1965).
 */
export const GRAVITY = 9.81;

/** Depth used for "deep water": tanh(k h) is 1 to double precision for every k we draw. */
export const DEEP = Number.POSITIVE_INFINITY;

/** Angular frequency ω (rad/s) of a wave of wavenumber k (rad/m) over water of depth h (m). */
export function angularFrequency(k: number, depth: number = DEEP): number {
  if (k <= 0) return 0;
  const t = Number.isFinite(depth) ? Math.tanh(k * depth) : 1;
  return Math.sqrt(GRAVITY * k * t);
}

/** dω/dk, the group velocity (m/s): needed to turn a frequency spectrum S(ω) into S(k). */
export function groupVelocity(k: number, depth: number = DEEP): number {
  if (k <= 0) return 0;
  if (!Number.isFinite(depth) || k * depth > 20) return 0.5 * Math.sqrt(GRAVITY / k);
  const kh = k * depth;
  const t = Math.tanh(kh);
  const omega = Math.sqrt(GRAVITY * k * t);
  const sech2 = 1 - t * t;
  // d(ω²)/dk = g tanh(kh) + g k h sech²(kh), and dω/dk = that / (2ω).
  return (GRAVITY * (t + kh * sech2)) / (2 * omega);
}

/** The wavenumber k whose frequency is ω: inverse of angularFrequency (Newton's method for finite depth). */
export function waveNumber(omega: number, depth: number = DEEP): number {
  if (omega <= 0) return 0;
  const deep = (omega * omega) / GRAVITY;
  if (!Number.isFinite(depth)) return deep;
  // Start from the larger of the deep and shallow (ω = k √(g h)) guesses; ω(k) is concave, so Newton converges from above.
  let k = Math.max(deep, omega / Math.sqrt(GRAVITY * depth));
  for (let i = 0; i < 60; i++) {
    const f = angularFrequency(k, depth) - omega;
    const step = f / groupVelocity(k, depth);
    k -= step;
    if (Math.abs(step) < 1e-14 * k) break;
  }
  return k;
}

/**
 * Tessendorf's quantised dispersion (2001, §3.2.1, eq. 17): round ω down to a whole multiple of
 * ω₀ = 2π/T, so that every wave, and hence the whole sea, repeats exactly every T seconds.
 * Then only t mod T matters: the CPU reduces t to [0, T) in float64 and the GPU never sees a
 * large float32 time (at t = 10⁶ s float32 spacing is 0.0625 s, a phase error of ω·0.03 rad).
 */
export function quantiseFrequency(omega: number, repeatPeriod: number): number {
  const omega0 = (2 * Math.PI) / repeatPeriod;
  return Math.floor(omega / omega0) * omega0;
}

/** t reduced into [0, T), computed in float64: the only time the quantised sea needs. */
export function timeInPeriod(time: number, repeatPeriod: number): number {
  const r = time % repeatPeriod;
  return r < 0 ? r + repeatPeriod : r;
}
