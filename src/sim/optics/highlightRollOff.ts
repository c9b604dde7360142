/**
 * The tone curve of the whole frame: what a display can show of light brighter than its white.
 *
 * The sun's glint and its disc are thousands of times brighter than the sky (SUN_IRRADIANCE
 * over the disc's small solid angle), and a display stops at 1. Clipping each channel at 1
 * would cut the glint's falloff off where it is still bright, and turn its edge into a hard
 * white ellipse. So, per channel:
 * - below the knee the colour is left exactly as it is: the water, the sky, the foam's grey;
 * - above it the excess rolls off exponentially towards white: f(x) = k + (1 − k)(1 − e^−(x−k)/(1−k)).
 *   The curve and its slope are continuous at the knee (slope 1 on both sides), and it rises
 *   all the way: radiance 1 (the sky cube's white) shows as 0.85, 1.5 as 0.96, 2 as 0.99, and
 *   an 8-bit screen, after the sRGB encoding, shows white from about 2.4 on (the sun's disc,
 *   most of the glint's core).
 *
 * It is the "shoulder" of film and of the filmic curves (Reinhard et al. 2002; Hable 2010),
 * without their toe: the darks stay linear, so the water's colour from optics shows as computed.
 * The app's renderer applies it to every pixel it draws (src/render/tone/wholeFrameToneCurve.ts):
 * the sea, the sky, the boat and the underwater passes alike.
 */

/** Where the roll-off starts, in linear colour (sRGB 203 of 255). */
export const HIGHLIGHT_KNEE = 0.6;

/** One channel through the curve (linear in, linear out, in [0, 1) for any finite light). */
export function rollOffHighlight(x: number): number {
  if (x <= HIGHLIGHT_KNEE) return x;
  return HIGHLIGHT_KNEE + (1 - HIGHLIGHT_KNEE) * (1 - Math.exp(-(x - HIGHLIGHT_KNEE) / (1 - HIGHLIGHT_KNEE)));
}

/** A linear RGB colour through the curve. */
export function rollOffHighlights(rgb: readonly [number, number, number]): [number, number, number] {
  return [rollOffHighlight(rgb[0]), rollOffHighlight(rgb[1]), rollOffHighlight(rgb[2])];
}
