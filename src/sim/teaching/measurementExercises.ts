import type { OceanParams } from '../params/params';
import { GRAVITY, groupVelocity } from '../waves/dispersion';
import { frequencySpectrum } from '../waves/spectra/waveSpectrum';
import { seaStateFromParams } from '../waves/spectra/seaState';
import { crestRadii, stoneGuideReach, waveFrontRadius } from '../iwave/cauchyPoissonRings';
import { WAVE_EQUATION_SPEED } from '../iwave/interactiveField';

/**
 * The lessons' measurements: the student reads a quantity off the live sea with one of the
 * sea tools and types it in; the card says whether it lies within tolerance of theory. The
 * theory is computed here from the live parameters with the same functions the sea and the
 * physics panel use, so changing the wind or the boat's speed changes what is expected.
 */

/** The tool the quantity is read with: the ruler (a drag on the sea) or the physics panel's "measured" column. */
export type ExerciseTool = 'ruler' | 'physics';

export type ExerciseQuantity = 'significantHeight' | 'peakPeriod' | 'transverseWavelength' | 'turningRadius' | 'ringRadius' | 'crestSpacing' | 'groupDistance';

/**
 * What the sea is doing at the moment of the check besides its parameters: how long ago the
 * last stone fell (null when none has), for the quantities that grow with time.
 */
export interface ExerciseMoment {
  stoneAge: number | null;
}

export interface MeasurementExercise {
  lesson: string;
  quantity: ExerciseQuantity;
  /** The symbol the card writes, e.g. Hs. */
  symbol: string;
  unit: 'm' | 's';
  tool: ExerciseTool;
  /**
   * Largest relative difference |measured / expected − 1| that passes. Set from how far the
   * tool's own reading scatters about theory (the physics panel's Hs within 3 %, its Tp within
   * 10 %), and tight enough that the usual slips (crest to trough for Hs, Tz for Tp, half a
   * wavelength) fail.
   */
  tolerance: number;
  /** `moment` left out: no stone has fallen. */
  expected(params: OceanParams, moment?: ExerciseMoment): number;
}

/** Hs = 4√m₀ of the wind spectrum the parameters choose (Holthuijsen 2007, §4.2). */
export function spectralSignificantHeight(params: OceanParams): number {
  return 4 * Math.sqrt(frequencySpectrum(seaStateFromParams(params)).m0);
}

/** Tp = 2π/ωp, the period of the wind spectrum's peak. */
export function spectralPeakPeriod(params: OceanParams): number {
  return (2 * Math.PI) / frequencySpectrum(seaStateFromParams(params)).peak;
}

/**
 * The Kelvin wake's transverse wavelength: the transverse waves keep pace with the boat, so
 * their phase speed √(g/k) equals its speed U, k = g/U², λ = 2πU²/g.
 */
export function transverseWakeWavelength(params: Pick<OceanParams, 'boatSpeed'>): number {
  return (2 * Math.PI * params.boatSpeed ** 2) / GRAVITY;
}

/** The radius of the circle a boat holding a turn runs on: its speed over its rate of turn, R = U/ω (ω in rad/s). */
export function turningRadius(params: Pick<OceanParams, 'boatSpeed' | 'boatTurnRate'>): number {
  return Math.abs(params.boatSpeed / ((params.boatTurnRate * Math.PI) / 180));
}

/** The plain wave equation's one ring `stoneAge` seconds after the stone: r = c t, c the field's wave speed. */
export function waveEquationRingRadius(moment?: ExerciseMoment): number {
  return moment === undefined || moment.stoneAge === null ? Number.NaN : waveFrontRadius(moment.stoneAge, WAVE_EQUATION_SPEED);
}

/**
 * The spacing of the stone's two outermost crests that the guide rings mark (those where
 * stationary phase holds and the field carries the waves), r_n − r_(n+1) with
 * r_n = g t²/(8πn) (Cauchy–Poisson; cauchyPoissonRings.ts).
 */
export function outerCrestSpacing(moment?: ExerciseMoment): number {
  if (moment === undefined || moment.stoneAge === null) return Number.NaN;
  const radii = crestRadii(moment.stoneAge, stoneGuideReach());
  return radii.length >= 2 ? radii[0] - radii[1] : Number.NaN;
}

/**
 * How far the group of the stone's outermost marked crest has run: that crest is the n-th, its
 * waves have k = 16π²n²/(g t²) (cauchyPoissonRings.ts), and their energy travels at the group
 * velocity, so they stand c_g(k)·t from the stone.
 */
export function outerGroupDistance(moment?: ExerciseMoment): number {
  if (moment === undefined || moment.stoneAge === null) return Number.NaN;
  const t = moment.stoneAge;
  const outer = crestRadii(t, stoneGuideReach())[0];
  if (outer === undefined) return Number.NaN;
  const n = Math.round((GRAVITY * t * t) / (8 * Math.PI * outer));
  const k = (16 * Math.PI * Math.PI * n * n) / (GRAVITY * t * t);
  return groupVelocity(k) * t;
}

const HS_TOLERANCE = 0.1;
const TP_TOLERANCE = 0.15;
const WAKE_TOLERANCE = 0.1;

const hs = (lesson: string): MeasurementExercise => ({
  lesson,
  quantity: 'significantHeight',
  symbol: 'Hs',
  unit: 'm',
  tool: 'physics',
  tolerance: HS_TOLERANCE,
  expected: spectralSignificantHeight,
});

const tp = (lesson: string): MeasurementExercise => ({
  lesson,
  quantity: 'peakPeriod',
  symbol: 'Tp',
  unit: 's',
  tool: 'physics',
  tolerance: TP_TOLERANCE,
  expected: spectralPeakPeriod,
});

const wake = (lesson: string): MeasurementExercise => ({
  lesson,
  quantity: 'transverseWavelength',
  symbol: 'λ',
  unit: 'm',
  tool: 'ruler',
  tolerance: WAKE_TOLERANCE,
  expected: transverseWakeWavelength,
});

/** The ruler reads to a few decimetres on a crest or a ring a few metres wide: 10 % of a radius or a spacing of metres. */
const RULER_TOLERANCE = 0.1;

const turn: MeasurementExercise = {
  lesson: 'wake-turn',
  quantity: 'turningRadius',
  symbol: 'R',
  unit: 'm',
  tool: 'ruler',
  tolerance: RULER_TOLERANCE,
  expected: turningRadius,
};

const ring: MeasurementExercise = {
  lesson: 'iwave-compare',
  quantity: 'ringRadius',
  symbol: 'r',
  unit: 'm',
  tool: 'ruler',
  tolerance: RULER_TOLERANCE,
  expected: (_params, moment) => waveEquationRingRadius(moment),
};

/** A crest found by eye on a train of crests 2–5 m apart: 15 %, still far from r_n itself or from twice the spacing. */
const crests: MeasurementExercise = {
  lesson: 'iwave-stone',
  quantity: 'crestSpacing',
  symbol: 'Δr',
  unit: 'm',
  tool: 'ruler',
  tolerance: 0.15,
  expected: (_params, moment) => outerCrestSpacing(moment),
};

const group: MeasurementExercise = {
  lesson: 'group-velocity',
  quantity: 'groupDistance',
  symbol: 'r',
  unit: 'm',
  tool: 'ruler',
  tolerance: RULER_TOLERANCE,
  expected: (_params, moment) => outerGroupDistance(moment),
};

export const MEASUREMENT_EXERCISES: readonly MeasurementExercise[] = [
  hs('fft-calm'),
  tp('fft-fresh-breeze'),
  tp('fft-short-fetch'),
  hs('fft-gale'),
  hs('physics-panel'),
  wake('kelvin-wake'),
  turn,
  ring,
  crests,
  group,
];

export function exerciseFor(lesson: string): MeasurementExercise | null {
  return MEASUREMENT_EXERCISES.find((exercise) => exercise.lesson === lesson) ?? null;
}

/** Whether a typed value lies within the exercise's tolerance of theory; a value that is not a finite number never does. */
export function withinTolerance(measured: number, expected: number, tolerance: number): boolean {
  if (!Number.isFinite(measured) || !Number.isFinite(expected) || expected === 0) return false;
  return Math.abs(measured / expected - 1) <= tolerance;
}
