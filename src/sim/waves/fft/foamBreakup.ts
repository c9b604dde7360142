import { smoothstep } from '../../math/smoothstep';
import { valueNoise } from '../../noise/valueNoise';
import { groupVelocity, waveNumber } from '../dispersion';
import { frequencySpectrum, peakWavelength } from '../spectra/waveSpectrum';
import { windVector, type SeaState } from '../spectra/seaState';

/**
 * What breaks the foam's repeat. Every FFT cascade repeats with its tile, and a cascade that
 * holds a third of the Jacobian's variance prints its period into the whitecaps: seen from
 * 400 m above, their pattern correlates with itself 0.12 one tile away (docs/light-tiling-and-crests.md).
 * Whitecaps do not fall on a lattice: waves break in groups (Donelan, Longuet-Higgins &
 * Turner 1972, "Periodicity in whitecaps", Nature 239), which travel at the group velocity of
 * the dominant waves. So the breaking measure is shifted by a smooth random field that does not
 * repeat (value noise on a lattice hashed by integerNoise, whose period is 2³² cells), of cells an
 * eighth of the peak wavelength wide, carried downwind at the peak's group velocity: the folds
 * inside a "group" break more readily, the others less. Its strength, in units of the breaking
 * measure's own spread, is what the no-tiling test needs (tests/browser/light/tiling.test.ts);
 * the threshold takes it into account, so the coverage stays Monahan's (breaking.ts).
 */
export const BREAKUP_CELLS_PER_PEAK_WAVELENGTH = 8;
export const BREAKUP_STRENGTH = 5;
/** Mixed into the hash with the user's seed, so the field differs from the seed's other noises. */
export const BREAKUP_STREAM = 0xf0a3;

export interface FoamBreakup {
  /** Width of the noise's lattice cells, m. */
  cell: number;
  /** Drift of the field, m/s (x, z): the peak's group velocity, downwind. */
  velocity: [number, number];
}

export function foamBreakup(sea: SeaState): FoamBreakup {
  const cell = peakWavelength(sea) / BREAKUP_CELLS_PER_PEAK_WAVELENGTH;
  const speed = groupVelocity(waveNumber(frequencySpectrum(sea).peak, sea.depth), sea.depth);
  const [wx, wz] = windVector(sea.windDirection);
  return { cell, velocity: [speed * wx, speed * wz] };
}

/**
 * The second octave's lattice, turned by 30° from the first and 2.31 times finer, so the two
 * lattices' axes and periods never line up: one octave alone draws its cells as squares.
 */
export const BREAKUP_SECOND_OCTAVE = { cos: Math.cos(Math.PI / 6), sin: Math.sin(Math.PI / 6), scale: 2.31, weight: 0.5 } as const;

/** The field's two octaves at lattice coordinates (u, v) (metres / cell), each in [−1, 1): foamBreakupOctaves's twin. */
export function breakupOctaves(u: number, v: number, seed: number): [first: number, second: number] {
  const s = (seed ^ BREAKUP_STREAM) | 0;
  const { cos, sin, scale } = BREAKUP_SECOND_OCTAVE;
  return [valueNoise(u, v, s), valueNoise(scale * (cos * u - sin * v), scale * (sin * u + cos * v), s)];
}

/** The field at lattice coordinates (u, v) (metres / cell): the TS twin of foamBreakup in shaders/foam/foamBreakup.glsl. */
export function breakupNoise(u: number, v: number, seed: number): number {
  const [first, second] = breakupOctaves(u, v, seed);
  const { weight } = BREAKUP_SECOND_OCTAVE;
  return (first + weight * second) / (1 + weight);
}

/**
 * A second field from the same octaves, uncorrelated with breakupNoise (their covariance,
 * ½ var − ½ var, is zero): foamBreakupOther's twin, which chooses between the tiles' copies
 * (tileCopies.ts).
 */
export function breakupOther([first, second]: [number, number]): number {
  const { weight } = BREAKUP_SECOND_OCTAVE;
  return (weight * first - second) / (1 + weight);
}

/**
 * Where the render origin (world x, z, m) and the drift at `time` put each octave's lattice,
 * split in double precision into whole cells and the rest, so the shader adds small numbers
 * only: the field at origin + r is breakupNoise(r / cell + first.offset + first.cells), the
 * second octave's lattice point the turned, scaled one (second.cells, second.offset).
 */
export function breakupLattice(
  breakup: FoamBreakup,
  originX: number,
  originZ: number,
  time: number,
): { cells: [number, number, number, number]; offset: [number, number, number, number] } {
  const u = (originX - breakup.velocity[0] * time) / breakup.cell;
  const v = (originZ - breakup.velocity[1] * time) / breakup.cell;
  const { cos, sin, scale } = BREAKUP_SECOND_OCTAVE;
  const su = scale * (cos * u - sin * v);
  const sv = scale * (sin * u + cos * v);
  const cells: [number, number, number, number] = [Math.floor(u), Math.floor(v), Math.floor(su), Math.floor(sv)];
  return { cells, offset: [u - cells[0], v - cells[1], su - cells[2], sv - cells[3]] };
}

/**
 * The share of the foam left behind that lies where a wave group lets it (foamGroupShare in
 * shaders/foam/foamBreakup.glsl): all of it in a group (the field below −0.6), none between
 * groups (above 0.2).
 */
export function foamGroupShare(breakup: number): number {
  return smoothstep(0.2, -0.6, breakup);
}

/** foamGroupShare's mean over the field (tests/unit/sim/waves/fft/windrows.test.ts measures it): the share everywhere without groups. */
export const FOAM_GROUP_SHARE_MEAN = 0.31;
