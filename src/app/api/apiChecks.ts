import { isValidTime, MAX_TIME } from '../../sim/params/simulationTime';
import { isCameraPose, type CameraPose } from '../camera/cameraPose';

/**
 * The automation API's argument checks: each throws a TypeError that says what was wanted,
 * before anything is changed, so a course page's mistake reads as a sentence.
 */
/** The URL's `t` range (src/sim/params/simulationTime.ts), so a time set here always makes a link that opens. */
export function checkTime(seconds: unknown): number {
  if (!isValidTime(seconds))
    throw new TypeError(`setTime needs a time in seconds between 0 and ${MAX_TIME} (as the URL's t), got ${String(seconds)}.`);
  return seconds;
}

export function checkCameraPose(pose: unknown): CameraPose {
  if (!isCameraPose(pose)) {
    throw new TypeError(
      'setCamera needs { position: [x, y, z], target: [x, y, z] }: finite numbers within ±1e6 m, the target apart from the position.',
    );
  }
  return pose;
}

export function checkSurfacePoint(x: number, z: number): void {
  if (!Number.isFinite(x) || !Number.isFinite(z))
    throw new TypeError(`sampleSurface needs finite x and z, got ${String(x)}, ${String(z)}.`);
}

export function checkProbe(points: unknown, time: unknown): [number, number][] {
  const valid =
    Array.isArray(points) &&
    points.every((p) => Array.isArray(p) && p.length === 2 && p.every((c) => typeof c === 'number' && Number.isFinite(c)));
  if (!valid) throw new TypeError('probeGpu needs an array of [x, z] pairs of finite numbers.');
  if (time !== undefined && !Number.isFinite(time)) throw new TypeError(`probeGpu's time must be a finite number, got ${String(time)}.`);
  return points as [number, number][];
}

export function checkBatches(batches: unknown): number | undefined {
  if (batches !== undefined && !(Number.isInteger(batches) && (batches as number) >= 1 && (batches as number) <= 1000)) {
    throw new TypeError(`lodUpdateMs needs a whole number of batches between 1 and 1000, got ${String(batches)}.`);
  }
  return batches as number | undefined;
}
