/**
 * The range of simulation times every entry point accepts (URL `t`, `setTime`, the
 * element's `t` attribute, share links): one rule, so a link made by the app always
 * opens. 1e9 s (≈ 32 years) keeps the shader's phases exact (see README, long runs).
 */
export const MAX_TIME = 1e9;

export function isValidTime(value: unknown): value is number {
  return typeof value === 'number' && Number.isFinite(value) && value >= 0 && value <= MAX_TIME;
}
