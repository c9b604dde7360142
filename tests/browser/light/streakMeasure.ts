import { highPass } from '../../support/highPass';

/**
 * How much the foam left behind is drawn out along the wind, from its own light seen from above
 * (the frame with foam less the same instant without), with the wind along the picture's x:
 * the anisotropy of its gradients, (Σ g_y² − Σ g_x²) / (Σ g_y² + Σ g_x²), 1 for streaks exactly
 * along the wind, 0 for round patches, negative for bands across it.
 * - The whitecaps breaking now are solid and long across the wind (their crests); they, and a
 *   guard of pixels around them, are left out, and the rest is capped at CAP levels.
 * - The lace's bubbles and its own stretched cells are finer than the box the light is first
 *   averaged over, so what is measured is the patches' shape.
 */
const WHITECAP_LEVELS = 120;
const GUARD = 4;
const CAP = 40;

export function streakAnisotropy(light: Float64Array, width: number, height: number, box: number): number {
  const keep = new Uint8Array(light.length).fill(1);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      if (light[y * width + x] <= WHITECAP_LEVELS) continue;
      for (let j = Math.max(0, y - GUARD); j <= Math.min(height - 1, y + GUARD); j++) {
        for (let i = Math.max(0, x - GUARD); i <= Math.min(width - 1, x + GUARD); i++) keep[j * width + i] = 0;
      }
    }
  }
  const capped = light.map((v) => Math.min(Math.max(v, 0), CAP));
  const fine = capped.slice();
  highPass(fine, width, height, box);
  const smooth = capped.map((v, i) => v - fine[i]);
  let along = 0;
  let across = 0;
  for (let y = 1; y < height - 1; y++) {
    for (let x = 1; x < width - 1; x++) {
      const i = y * width + x;
      if (!keep[i]) continue;
      along += ((smooth[i + 1] - smooth[i - 1]) / 2) ** 2;
      across += ((smooth[i + width] - smooth[i - width]) / 2) ** 2;
    }
  }
  return (across - along) / (across + along);
}
