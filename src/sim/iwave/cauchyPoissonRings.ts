import { GRAVITY } from '../wake/kelvinWake';
import { IWAVE_GRID_SIZE, IWAVE_SPACING } from './fieldSize';
import { IWAVE_SPONGE } from './iwaveGrid';
import { IWAVE_KERNEL_BAND } from './verticalDerivativeKernel';

/** The least phase g t²/(4r), rad, where stationary phase describes a stone's waves: 12 leaves out the first crest. */
export const STATIONARY_PHASE_FROM = 12;

/**
 * Where a dropped stone's crests must stand `age` seconds after it fell, on deep water: the
 * teaching guide of the `stone` preset. For an initial bump of volume Q at rest, stationary
 * phase gives η(r, t) ≈ A(r, t) cos(g t² / (4 r)) with A > 0 (Lamb, Hydrodynamics, §255; the
 * phase of kr − ωt at k = g t²/(4r²), plus the π/4 of stationary phase, less the Bessel
 * function's π/4). Crests stand where g t²/(4r) = 2πn, r_n = g t²/(8πn), and the waves there
 * have k = g t²/(4 r_n²) = 16π²n²/(g t²).
 *
 * Only crests where the formula holds and the field carries the waves are returned: phase at
 * least `minPhase` (the stationary-phase region; 12 rad leaves out the first crest, n = 1),
 * k within [kMin, kMax], radius at most `maxRadius`. Outermost first.
 */
export function crestRadii(
  age: number,
  options: { kMin: number; kMax: number; maxRadius: number; minPhase?: number; gravity?: number },
): number[] {
  const g = options.gravity ?? GRAVITY;
  const minPhase = options.minPhase ?? STATIONARY_PHASE_FROM;
  if (!(age > 0)) return [];
  const radii: number[] = [];
  for (let n = 1; ; n++) {
    const k = (16 * Math.PI * Math.PI * n * n) / (g * age * age);
    if (k > options.kMax) break;
    const r = (g * age * age) / (8 * Math.PI * n);
    if (2 * Math.PI * n >= minPhase && k >= options.kMin && r <= options.maxRadius) radii.push(r);
  }
  return radii;
}

/** The one ring of the plain wave equation ∂²h/∂t² = c²∇²h: its front has run c·t. */
export function waveFrontRadius(age: number, speed: number): number {
  return age > 0 ? speed * age : 0;
}

/**
 * What the guide rings are limited to: the band of wavenumbers the field carries (rad/m) and
 * the radius inside its sponge (m), past which the field is being absorbed.
 */
export function stoneGuideReach(): { kMin: number; kMax: number; maxRadius: number } {
  const [kMin, kMax] = IWAVE_KERNEL_BAND.map((k) => k / IWAVE_SPACING);
  return { kMin, kMax, maxRadius: (0.5 * IWAVE_GRID_SIZE - IWAVE_SPONGE.width) * IWAVE_SPACING };
}
