import { describe, expect, it } from 'vitest';
import { addWake, BoatWake, replayedPosition, wakeHeightBound, type WakeControls } from '../../../../src/sim/wake/boatWake';
import { forwardOf, starboardOf } from '../../../../src/sim/boat/boatPose';
import type { WakeUniformData } from '../../../../src/sim/wake/wakeUniformData';

const ON = { enabled: true, strength: 1 };
const DEG = Math.PI / 180;

describe('the boat wake as the app keeps it', () => {
  // Two views of one frozen instant get the same uniforms.
  it('replays a fresh track from the time, pose and controls alone', () => {
    const c: WakeControls = { x: 1200.5, z: -800.25, heading: 270 * DEG, speed: 4, turnRate: 3 * DEG };
    const a = new BoatWake();
    const b = new BoatWake();
    // One view was playing before it jumped here (setTime), the other opened at this instant.
    for (let t = 5; t < 7; t += 1 / 60) a.record(t, { ...c, x: c.x - 300 });
    a.record(3000, c);
    b.record(3000, c);
    const ua = a.uniforms(3000, ON);
    const ub = b.uniforms(3000, ON);
    expect(ua.count).toBeGreaterThan(60);
    expect(Array.from(ua.track)).toEqual(Array.from(ub.track));
    expect(ua.origin).toEqual(ub.origin);
  });

  it("lays a turning boat's replay on its circle (radius U/ω) within 1 cm, and a straight one on its line", () => {
    const c: WakeControls = { x: 7, z: -5, heading: 270 * DEG, speed: 4, turnRate: 3 * DEG };
    const radius = c.speed / c.turnRate;
    const [sx, sz] = starboardOf(c.heading);
    const centre = [c.x + sx * radius, c.z + sz * radius];
    let worst = 0;
    for (let age = 1; age <= 80; age += 1.5) {
      const [x, z] = replayedPosition(c, age);
      worst = Math.max(worst, Math.abs(Math.hypot(x - centre[0], z - centre[1]) - radius));
    }
    expect(worst).toBeLessThan(0.01);
    // Negative control: the same sources laid on the straight course stray tens of metres from the circle.
    const straight = replayedPosition({ ...c, turnRate: 0 }, 40);
    const [fx, fz] = forwardOf(c.heading);
    expect(straight[0]).toBeCloseTo(c.x - fx * 160, 9);
    expect(straight[1]).toBeCloseTo(c.z - fz * 160, 9);
    expect(Math.abs(Math.hypot(straight[0] - centre[0], straight[1] - centre[1]) - radius)).toBeGreaterThan(50);
  });

  it('replays again when a frozen view is given new controls, and records real motion once the clock runs', () => {
    const w = new BoatWake();
    const c: WakeControls = { x: 0, z: 0, heading: 0, speed: 3, turnRate: 0 };
    w.record(10, c);
    const slow = w.uniforms(10, ON).track.slice();
    w.record(10, { ...c, speed: 6 });
    const fast = w.uniforms(10, ON).track;
    // The oldest sources lie twice as far back at twice the speed.
    expect(Math.abs(fast[4 * 40 + 1] / slow[4 * 40 + 1] - 2)).toBeLessThan(1e-3);
    // The clock runs: a new heading is steering, recorded, not a new replay (the old track stays behind the boat).
    w.record(10.5, { ...c, speed: 6, z: -3, heading: 90 * DEG });
    const after = w.uniforms(10.5, ON);
    expect(after.track[4 * 40 + 1]).toBeCloseTo(fast[4 * 40 + 1] + 3, 3);
  });

  it("is off with wake off: no sources, and sampleSurface's sum is then the model's sample itself", () => {
    const w = new BoatWake();
    w.record(10, { x: 0, z: 0, heading: 0, speed: 4, turnRate: 0 });
    const off = w.uniforms(10, { enabled: false, strength: 1 });
    expect(off.count).toBe(0);
    expect(wakeHeightBound(off)).toBe(0);
    expect(w.at(0, 20, 10, { enabled: false, strength: 1 })).toEqual([0, 0, 0]);
    expect(w.at(0, 20, 10, ON)[0]).not.toBe(0);
  });

  // Negative control: the head segment alone does not.
  it('bounds |η| everywhere it was sampled, at 2, 4, 8 and 12 m/s and on a turn', () => {
    for (const [speed, turn] of [
      [2, 0],
      [4, 0],
      [8, 0],
      [12, 0],
      [4, 3],
    ]) {
      const w = new BoatWake();
      w.record(100, { x: 0, z: 0, heading: 90 * DEG, speed, turnRate: turn * DEG });
      const data = w.uniforms(100, ON);
      let max = 0;
      for (let x = -120; x <= 10; x += 2) for (let z = -40; z <= 40; z += 2) max = Math.max(max, Math.abs(w.at(x, z, 100, ON)[0]));
      const bound = wakeHeightBound(data);
      // Measured: max |η| 0.34, 0.70, 0.46, 0.39, 0.69 m against a bound of 4.79 m (the bound adds every segment's largest term).
      expect(max, `U = ${speed}`).toBeLessThan(bound);
      const headOnly: WakeUniformData = { ...data, count: 2 };
      expect(wakeHeightBound(headOnly), `U = ${speed}`).toBeLessThan(max);
    }
  }, 30_000);

  // Negative control: slopes added to n unscaled.
  it('adds the wake to a model sample: heights add, the normal is that of the summed slopes', () => {
    // A plane of slopes (0.6, −0.3) under a wake of slope (0.2, 0.5).
    const n = [-0.6, 1, 0.3];
    const len = Math.hypot(...n);
    const sample = { height: 1.5, normal: [n[0] / len, n[1] / len, n[2] / len] as [number, number, number] };
    const out = addWake(sample, [0.25, 0.2, 0.5]);
    expect(out.height).toBe(1.75);
    const expected = [-(0.6 + 0.2), 1, -(-0.3 + 0.5)];
    const e = Math.hypot(...expected);
    out.normal.forEach((v, i) => expect(v).toBeCloseTo(expected[i] / e, 12));
    const naive = [sample.normal[0] - 0.2, sample.normal[1], sample.normal[2] - 0.5];
    const nl = Math.hypot(...naive);
    // Off by 1e-2 where the kept test holds to 1e-12.
    expect(Math.max(...naive.map((v, i) => Math.abs(v / nl - expected[i] / e)))).toBeGreaterThan(1e-3);
  });
});

describe('the wake in a share link', () => {
  it('a link made while sailing restores the very track, bit for bit: the reopened view does not replay it', async () => {
    const { parseSettings, formatUrlState } = await import('../../../../src/app/url/urlState');
    const { defaultParams } = await import('../../../../src/sim/params/params');
    const live = new BoatWake();
    // Sailing and steering: a track no replay of the present course would make.
    let x = 0;
    let z = 0;
    for (let i = 0; i <= 40 * 60; i++) {
      const t = 100 + i / 60;
      const heading = i < 20 * 60 ? 0 : 60 * DEG;
      live.record(t, { x, z, heading, speed: 4, turnRate: 0 });
      const [fx, fz] = forwardOf(heading);
      x += (fx * 4) / 60;
      z += (fz * 4) / 60;
    }
    const time = 100 + 40;
    const params = { ...defaultParams(), wake: true };
    const link = formatUrlState({
      params,
      time,
      camera: { position: [0, 10, 10], target: [0, 0, 0] },
      language: 'en',
      sky: null,
      boat: null,
      embed: false,
      wakeTrack: live.track.serialize(),
    });
    const state = parseSettings(new URLSearchParams(link));
    expect(state.notices).toEqual([]);
    const head = live.track.fine.latest()!;
    const restored = new BoatWake();
    restored.restore(state.wakeTrack!);
    restored.record(time, { x: head.x, z: head.z, heading: 60 * DEG, speed: 4, turnRate: 0 });
    const a = live.uniforms(time, ON).track;
    const b = restored.uniforms(time, ON).track;
    let worst = 0;
    for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
    expect(worst).toBe(0);
    // Control: without the track the link replays the present course, a straight line, far from the bend.
    const replayed = new BoatWake();
    replayed.record(time, { x: head.x, z: head.z, heading: 60 * DEG, speed: 4, turnRate: 0 });
    const c = replayed.uniforms(time, ON).track;
    let off = 0;
    for (let i = 0; i < a.length; i++) off = Math.max(off, Math.abs(a[i] - c[i]));
    expect(off).toBeGreaterThan(10);
    // A link with the wake off carries no track; a mangled one gives a notice and no track.
    expect(
      formatUrlState({
        params: defaultParams(),
        time,
        camera: { position: [0, 10, 10], target: [0, 0, 0] },
        language: 'en',
        sky: null,
        boat: null,
        embed: false,
        wakeTrack: live.track.serialize(),
      }),
    ).not.toContain('wakeTrack');
    const bad = parseSettings(new URLSearchParams('wakeTrack=0.5;3;1,2,3|'));
    expect(bad.wakeTrack).toBeNull();
    expect(bad.notices.map((n) => n.id)).toEqual(['wakeTrackInvalid']);
  });
});
