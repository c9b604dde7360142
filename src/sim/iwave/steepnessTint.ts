import { smoothstep } from '../math/smoothstep';

/**
 * How the interactive field marks its steep water: light through a thin, steep crest (a paler,
 * greener water colour), and foam where a wave nears breaking. The GLSL twin is
 * iwaveTint / iwaveFoam in shaders/iwave.glsl, which reads these numbers as #defines.
 *
 * The scale is the steepest wave there is: Stokes's limiting wave has a 120° corner at its
 * crest (Stokes 1880), so its slope reaches tan 30° = 0.577 there. Foam begins at 60 % of
 * that and covers the water at the limit; the tint begins at a slope of 0.03, about what a
 * stone's rings have 10 s on, and is full at the foam's start.
 */
export const STOKES_LIMIT_SLOPE = Math.tan(Math.PI / 6);
export const TINT_FROM_SLOPE = 0.03;
export const FOAM_FROM_SLOPE = 0.6 * STOKES_LIMIT_SLOPE;
/** The largest share of the water colour the tint replaces. */
export const TINT_STRENGTH = 0.6;
/**
 * The tint's colour (linear RGB): green-blue, as light is that has crossed a thin crest, red
 * being absorbed within metres of water (Pope & Fry 1997) and blue scattered back on the way.
 * Picked by eye within that; not computed.
 */
export const CREST_COLOR: readonly [number, number, number] = [0.05, 0.32, 0.3];

/** The share of CREST_COLOR mixed into the water's colour where the field's slope is (sx, sz). */
export function fieldTint(sx: number, sz: number): number {
  return TINT_STRENGTH * smoothstep(TINT_FROM_SLOPE, FOAM_FROM_SLOPE, Math.hypot(sx, sz));
}

/** Foam, 0 to 1, where the field's slope is (sx, sz): none below FOAM_FROM_SLOPE, full at Stokes's limit. */
export function fieldFoam(sx: number, sz: number): number {
  return smoothstep(FOAM_FROM_SLOPE, STOKES_LIMIT_SLOPE, Math.hypot(sx, sz));
}
