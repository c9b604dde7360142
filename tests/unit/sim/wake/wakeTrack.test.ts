import { describe, expect, it } from 'vitest';
import {
  TRACK_COARSE_INTERVAL,
  TRACK_INTERVAL,
  TRACK_POINTS,
  TrackRecorder,
  WakeTrack,
  parseTrack,
  serializeTrack,
} from '../../../../src/sim/wake/wakeTrack';

/** A boat on a circle of 50 m radius at 5 m/s, position at time t. */
const circle = (t: number): [number, number] => [50 * Math.sin(t / 10), 50 - 50 * Math.cos(t / 10)];

/** Records the circle from t0 to t1 with frames of `dt` seconds (the last frame lands on t1). */
function recordCircle(track: WakeTrack | TrackRecorder, t0: number, t1: number, dt: number): void {
  const n = Math.round((t1 - t0) / dt);
  for (let i = 0; i <= n; i++) {
    const t = i === n ? t1 : t0 + i * dt;
    const [x, z] = circle(t);
    track.record(t, x, z, 5);
  }
}

describe('TrackRecorder', () => {
  it('samples at the fixed instants k·interval, whatever the frame rate (to the interpolation error of one frame)', () => {
    const a = new TrackRecorder();
    const b = new TrackRecorder();
    recordCircle(a, 3.01, 20.3, 1 / 60);
    recordCircle(b, 3.01, 20.3, 1 / 23);
    const sa = a.state().samples;
    const sb = b.state().samples;
    expect(sa.length).toBe(sb.length);
    for (let i = 0; i < sa.length; i++) {
      expect(sa[i].time).toBe(sb[i].time);
      expect(Number.isInteger(sa[i].time / TRACK_INTERVAL)).toBe(true);
      // A chord of a 50 m circle over 1/23 s at 5 m/s is off the arc by 5e-6 m.
      expect(Math.hypot(sa[i].x - sb[i].x, sa[i].z - sb[i].z)).toBeLessThan(1e-4);
      const [x, z] = circle(sa[i].time);
      expect(Math.hypot(sa[i].x - x, sa[i].z - z)).toBeLessThan(1e-4);
    }
  });

  it('keeps only the newest `capacity` samples, newest first in points(), head first', () => {
    const r = new TrackRecorder(0.5, 8);
    recordCircle(r, 0, 30.2, 0.1);
    const points = r.points();
    expect(points.length).toBe(9);
    expect(points[0].time).toBeCloseTo(30.2, 12);
    expect(points.slice(1).map((p) => p.time)).toEqual([30, 29.5, 29, 28.5, 28, 27.5, 27, 26.5]);
  });

  it('starts a fresh track after a step back in time or a jump longer than a second', () => {
    const r = new TrackRecorder();
    recordCircle(r, 0, 10, 0.1);
    r.record(5, 0, 0, 5);
    expect(r.points().length).toBe(1);
    recordCircle(r, 5, 8, 0.1);
    r.record(20, 0, 0, 5);
    expect(r.points().length).toBe(1);
  });

  it('round-trips through its share-link text to the centimetre', () => {
    const r = new TrackRecorder();
    recordCircle(r, 1.234, 14.567, 1 / 60);
    const text = serializeTrack(r.state());
    const back = TrackRecorder.fromState(parseTrack(text));
    const p = r.points();
    const q = back.points();
    expect(q.length).toBe(p.length);
    for (let i = 0; i < p.length; i++) {
      expect(Math.abs(q[i].x - p[i].x)).toBeLessThanOrEqual(0.005 + 1e-9);
      expect(Math.abs(q[i].z - p[i].z)).toBeLessThanOrEqual(0.005 + 1e-9);
      expect(Math.abs(q[i].time - p[i].time)).toBeLessThanOrEqual(0.0005 + 1e-9);
    }
  });

  it('rejects text whose samples are not one interval apart or are not numbers (negative controls)', () => {
    expect(() =>
      TrackRecorder.fromState({
        interval: 0.5,
        samples: [
          { x: 0, z: 0, time: 1, speed: 1 },
          { x: 0, z: 0, time: 2, speed: 1 },
        ],
        head: { x: 0, z: 0, time: 2.1, speed: 1 },
      }),
    ).toThrow();
    expect(() => parseTrack('0.5;2;1,2,x|1,2,3,4')).toThrow();
    expect(() => parseTrack('0.5;2;1,2,3')).toThrow();
  });
});

describe('WakeTrack', () => {
  it('joins 0.5 s samples for the last 16 s to 2 s samples behind them, at most TRACK_POINTS points, ages increasing', () => {
    const t = new WakeTrack();
    recordCircle(t, 0, 200.3, 1 / 30);
    const points = t.points();
    expect(points.length).toBe(TRACK_POINTS);
    const ages = points.map((p) => 200.3 - p.time);
    for (let i = 1; i < ages.length; i++) expect(ages[i]).toBeGreaterThan(ages[i - 1]);
    expect(ages[1]).toBeCloseTo(0.3, 9);
    expect(ages[32]).toBeCloseTo(15.8, 9);
    expect(ages[33] - ages[32]).toBeLessThanOrEqual(TRACK_COARSE_INTERVAL);
    // The wake's history taper ends at 76 s: the track must reach at least that far back.
    expect(ages[ages.length - 1]).toBeGreaterThanOrEqual(76);
  });

  it('is the same after a share-link round trip (to the centimetre) and the same whatever the frame rate', () => {
    const a = new WakeTrack();
    const b = new WakeTrack();
    recordCircle(a, 0, 100.5, 1 / 60);
    recordCircle(b, 0, 100.5, 1 / 37);
    const c = WakeTrack.parse(a.serialize());
    const [pa, pb, pc] = [a.points(), b.points(), c.points()];
    expect(pb.length).toBe(pa.length);
    expect(pc.length).toBe(pa.length);
    for (let i = 0; i < pa.length; i++) {
      expect(pb[i].time).toBe(pa[i].time);
      expect(Math.hypot(pb[i].x - pa[i].x, pb[i].z - pa[i].z)).toBeLessThan(1e-4);
      expect(Math.hypot(pc[i].x - pa[i].x, pc[i].z - pa[i].z)).toBeLessThan(0.0071);
    }
  });
});
