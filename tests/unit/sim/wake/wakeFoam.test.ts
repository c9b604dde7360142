import { describe, expect, it } from 'vitest';
import { wakeFoam, type FoamParams } from '../../../../src/sim/wake/wakeFoam';
import { WakeTrack } from '../../../../src/sim/wake/wakeTrack';

const HULL: FoamParams = { hullLength: 8, hullBeam: 2.6 };
const FRAME = 1 / 30;

/** A boat from (0, 0) along +x at `speed` for `duration` s, recorded every frame. */
function sail(speed: number, duration: number) {
  const track = new WakeTrack();
  const frames = Math.round(duration / FRAME);
  for (let i = 0; i <= frames; i++) track.record(i * FRAME, speed * i * FRAME, 0, speed);
  return { points: track.points(), time: frames * FRAME, headX: speed * frames * FRAME };
}

describe('wakeFoam', () => {
  const { points, time, headX } = sail(5, 120);
  /** Foam on the path, `age` seconds behind the boat. */
  const onPath = (age: number, params = HULL) => wakeFoam(headX - 5 * age, 0, time, points, params);

  // Measured: 0.95 at 1 s, 0.60 at 10 s, 0.05 at 60 s (e-folding 20 s, band widening).
  it('leaves a trail on the path that decays over tens of seconds', () => {
    const fresh = onPath(1);
    expect(fresh).toBeGreaterThan(0.5);
    expect(onPath(10)).toBeGreaterThan(0.4 * fresh);
    expect(onPath(60)).toBeLessThan(0.1 * fresh);
  });

  it('fades within seconds with a 1 s decay (negative control)', () => {
    const quick = { ...HULL, trailDecay: 1, bowDecay: 1 };
    expect(onPath(10, quick)).toBeLessThan(0.4 * onPath(1, quick));
  });

  it('has none ahead of the bow and none far to the side', () => {
    expect(wakeFoam(headX + 10, 0, time, points, HULL)).toBeLessThan(1e-6);
    expect(wakeFoam(headX - 20, 40, time, points, HULL)).toBeLessThan(1e-6);
  });

  // Measured: 0.62 on the line, 0.037 at 5 m off the path.
  it('draws the bow wave as two lines off the path, brighter than the water between them and the trail', () => {
    // 3 s behind: the bow wave's line is at 1.3 + 0.36·5·(3 + 0.8) = 8.1 m off the path.
    const x = headX - 15;
    const line = wakeFoam(x, 8.1, time, points, HULL);
    const between = wakeFoam(x, 5, time, points, HULL);
    expect(line).toBeGreaterThan(0.3);
    expect(line).toBeGreaterThan(3 * between);
    expect(wakeFoam(x, -8.1, time, points, HULL)).toBeCloseTo(line, 9);
  });

  it('makes no foam behind a boat too slow to break the water (Fr < 0.1)', () => {
    const slow = sail(0.8, 60);
    expect(wakeFoam(slow.headX - 2, 0, slow.time, slow.points, HULL)).toBe(0);
  });
});
