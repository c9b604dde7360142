import { smoothstep } from '../../math/smoothstep';
import { valueNoise } from '../../noise/valueNoise';
import { windVector, type SeaState } from '../spectra/seaState';
import { foamDriftVelocity } from './foamDrift';
import { FOAM_GROUP_SHARE_MEAN } from './foamBreakup';

/**
 * Windrows: in a strong wind the foam left behind lies in streaks along the wind. The Beaufort
 * scale's sea criteria (as the WMO adopted them; the UK Met Office's table has the same words)
 * say when: at force 7 (from 13.9 m/s) "foam from breaking waves begins to be blown in streaks
 * along the direction of the wind", at force 8 "well-marked streaks", at force 9 (from
 * 20.8 m/s) "dense streaks of foam along the direction of the wind". What gathers the foam is
 * Langmuir circulation: pairs of vortices with their axes along the wind, whose surface flow
 * converges on lines a few metres to a few hundred metres apart, where whatever floats
 * collects (Langmuir 1938, Science 87; Leibovich 1983, Annu. Rev. Fluid Mech. 15).
 *
 * Here, in a strong wind, where the foam left behind lies is no longer where its wave group
 * broke (foamGroupShare) but where the windrows sweep it: value noise on a lattice laid along
 * the wind, its cells WINDROW_STRETCH times longer along it than across, carried with the
 * surface's wind drift as the foam is (foamDrift.ts). The windrows' share has the groups' mean,
 * FOAM_GROUP_SHARE_MEAN, so the foam is moved, not made. The strength of the hand-over grows
 * from nothing at force 7's lower bound to all of it at force 9's.
 */
/** A lattice cell across the wind, m: the streaks lie about two cells apart. */
export const WINDROW_SPACING = 6;
/** How many times longer a cell is along the wind than across it. */
export const WINDROW_STRETCH = 12;
/** Mixed into the hash with the user's seed, so the windrows differ from the seed's other noises. */
export const WINDROW_STREAM = 0x51d3;
/** The lower bounds of Beaufort forces 7 and 9, m/s at 10 m. */
export const BEAUFORT_7_FROM = 13.9;
export const BEAUFORT_9_FROM = 20.8;
/** Where the noise gathers the foam: none at or below FROM, all of it from TO. */
export const WINDROW_GATHER_FROM = 0.15;
export const WINDROW_GATHER_TO = 0.5;
/** The gathering's mean over the noise (tests/unit/sim/waves/fft/windrows.test.ts measures it), so the windrows' share has the groups' mean. */
export const WINDROW_GATHER_MEAN = 0.269;

/** How much of the gathering the wind makes: 0 up to Beaufort 7, 1 from Beaufort 9. */
export function windrowStrength(windSpeed: number): number {
  return smoothstep(BEAUFORT_7_FROM, BEAUFORT_9_FROM, windSpeed);
}

/** The share of the noise's foam gathered at noise value n, in [0, 1]. */
export function windrowGathering(noise: number): number {
  return smoothstep(WINDROW_GATHER_FROM, WINDROW_GATHER_TO, noise);
}

/**
 * The share of the foam left behind that lies at lattice coordinates (u along, v across the
 * wind), given the share its group would let lie: foamWindrowShare's twin (shaders/foam/foamWindrows.glsl),
 * for a pixel that spans under a quarter of a cell (a wider one hands back to the groups there).
 */
export function windrowShare(u: number, v: number, seed: number, strength: number, groupShare: number): number {
  const swept = (FOAM_GROUP_SHARE_MEAN * windrowGathering(valueNoise(u, v, (seed ^ WINDROW_STREAM) | 0))) / WINDROW_GATHER_MEAN;
  return groupShare + strength * (swept - groupShare);
}

export interface WindrowLattice {
  /** Lattice coordinates per metre of (x, z): u = dot(axes[0..1], r), v = dot(axes[2..3], r). */
  axes: [number, number, number, number];
  /** Whole cells and the rest where the render origin falls on the lattice at this time. */
  cells: [number, number];
  offset: [number, number];
}

/**
 * The windrows' lattice for this sea at `time`, with the render origin (world x, z, m) split in
 * double precision into whole cells and the rest, so the shader adds small numbers only: the
 * windrows' share at origin + r is windrowShare at axes · r + offset + cells.
 */
export function windrowLattice(
  sea: Pick<SeaState, 'windSpeed' | 'windDirection'>,
  originX: number,
  originZ: number,
  time: number,
): WindrowLattice {
  const [wx, wz] = windVector(sea.windDirection);
  const along = 1 / (WINDROW_STRETCH * WINDROW_SPACING);
  const across = 1 / WINDROW_SPACING;
  const axes: [number, number, number, number] = [wx * along, wz * along, -wz * across, wx * across];
  const [vx, vz] = foamDriftVelocity(sea);
  const x = originX - vx * time;
  const z = originZ - vz * time;
  const u = axes[0] * x + axes[1] * z;
  const v = axes[2] * x + axes[3] * z;
  const cells: [number, number] = [Math.floor(u), Math.floor(v)];
  return { axes, cells, offset: [u - cells[0], v - cells[1]] };
}

/** The lattice coordinates (u along, v across the wind) of the point origin + (rx, rz): what foamWindrowShare works out from the uniforms. */
export function windrowCoordinates(lattice: WindrowLattice, rx: number, rz: number): [u: number, v: number] {
  const [ax, az, bx, bz] = lattice.axes;
  return [ax * rx + az * rz + lattice.offset[0] + lattice.cells[0], bx * rx + bz * rz + lattice.offset[1] + lattice.cells[1]];
}
