import { describe, expect, it } from 'vitest';
import { forwardOf, hullSamplePoints, poseAxes, starboardOf, targetPose, type HullSize } from '../../../../src/sim/boat/boatPose';
import { followStep, type FollowerState } from '../../../../src/sim/boat/dampedFollower';
import { ANGLE_BAND, BOAT_EXTENT, BoatMotion, HEAVE_BAND } from '../../../../src/sim/boat/boatMotion';
import { FftOcean } from '../../../../src/sim/waves/fft/fftOcean';
import { FftWaveModel } from '../../../../src/sim/waves/fft/fftWaveModel';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';
import { GerstnerLiveModel } from '../../../../src/sim/waves/gerstner/gerstnerLiveModel';
import { defaultParams } from '../../../../src/sim/params/params';
import type { LiveWaveModel } from '../../../../src/sim/waves/waveModel';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

const HULL: HullSize = { length: 8, beam: 2.6 };
const dot = (a: number[], b: number[]) => a.reduce((s, v, i) => s + v * b[i], 0);

describe('targetPose', () => {
  // Half a length and half a beam from the centre.
  it('samples the surface at exactly the five hull points the lessons draw', () => {
    const heading = 0.7;
    const asked: [number, number][] = [];
    targetPose((x, z) => (asked.push([x, z]), 0), 12, -40, heading, HULL);
    const points = hullSamplePoints(12, -40, heading, HULL);
    expect(asked).toEqual([points.centre, points.bow, points.stern, points.starboard, points.port]);
    const distance = (p: [number, number]) => Math.hypot(p[0] - 12, p[1] + 40);
    expect(distance(points.bow)).toBeCloseTo(4, 12);
    expect(distance(points.port)).toBeCloseTo(1.3, 12);
    // The bow lies ahead: along forwardOf(heading), not astern (control: the stern is behind).
    expect(dot([points.bow[0] - 12, points.bow[1] + 40], forwardOf(heading))).toBeCloseTo(4, 12);
    expect(dot([points.stern[0] - 12, points.stern[1] + 40], forwardOf(heading))).toBeCloseTo(-4, 12);
    expect(dot([points.starboard[0] - 12, points.starboard[1] + 40], starboardOf(heading))).toBeCloseTo(1.3, 12);
  });

  it('lies level at the water height on a flat sea, whatever the heading', () => {
    for (const heading of [0, 0.7, Math.PI, -2.1]) {
      const pose = targetPose(() => 0.35, 12, -40, heading, HULL);
      expect(pose).toEqual({ x: 12, y: 0.35, z: -40, heading, pitch: 0, roll: 0 });
    }
  });

  it('follows the sign conventions: bow up on a slope rising ahead, starboard up on a slope rising to the right', () => {
    // Heading 0 sails towards −z; the sea rising towards −z lifts the bow.
    expect(targetPose((_x, z) => -0.1 * z, 0, 0, 0, HULL).pitch).toBeCloseTo(Math.atan(0.1), 12);
    // Starboard is +x at heading 0: rising towards +x lifts starboard.
    expect(targetPose((x) => 0.1 * x, 0, 0, 0, HULL).roll).toBeCloseTo(Math.atan(0.1), 12);
    // Heading π/2 sails towards +x: the same sea now lifts the bow, and starboard (+z) is level.
    const east = targetPose((x) => 0.1 * x, 0, 0, Math.PI / 2, HULL);
    expect(east.pitch).toBeCloseTo(Math.atan(0.1), 12);
    expect(east.roll).toBeCloseTo(0, 12);
    expect(forwardOf(Math.PI / 2)[0]).toBeCloseTo(1, 12);
    expect(starboardOf(0)).toEqual([1, 0]);
  });

  it('heaves by the height at the centre, not at the ends', () => {
    const pose = targetPose((x, z) => (Math.abs(x) < 0.5 && Math.abs(z) < 0.5 ? 2 : 0), 0, 0, 0.3, HULL);
    expect(pose.y).toBe(2);
    expect(pose.pitch).toBe(0);
    expect(pose.roll).toBe(0);
  });

  it('on random planes (seed 515) puts the up axis on the plane normal and the keel in the plane', () => {
    const random = seededRandom(515);
    for (let i = 0; i < 200; i++) {
      const a = (random() * 2 - 1) * 0.6;
      const b = (random() * 2 - 1) * 0.6;
      const c = random() * 3;
      const heading = random() * Math.PI * 2;
      const x = (random() * 2 - 1) * 500;
      const z = (random() * 2 - 1) * 500;
      const pose = targetPose((px, pz) => a * px + b * pz + c, x, z, heading, HULL);
      expect(pose.y).toBeCloseTo(a * x + b * z + c, 9);
      const n = [-a, 1, -b].map((v) => v / Math.hypot(a, 1, b));
      const axes = poseAxes(pose);
      axes.up.forEach((v, k) => expect(v).toBeCloseTo(n[k], 12));
      expect(dot(axes.forward, n)).toBeCloseTo(0, 12);
      expect(dot(axes.starboard, n)).toBeCloseTo(0, 12);
      // The keel still points along the heading seen from above.
      const [fx, fz] = forwardOf(heading);
      expect(Math.atan2(axes.forward[0], -axes.forward[2])).toBeCloseTo(Math.atan2(fx, -fz), 12);
    }
  });
});

describe('followStep', () => {
  it('converges on a fixed target without overshoot, the same for any split of the time', () => {
    let coarse: FollowerState = { value: 1, velocity: 0 };
    let fine: FollowerState = { value: 1, velocity: 0 };
    for (let i = 0; i < 50; i++) coarse = followStep(coarse, 0, 0.1, 4, 10);
    for (let i = 0; i < 500; i++) {
      fine = followStep(fine, 0, 0.01, 4, 10);
      expect(fine.value).toBeGreaterThanOrEqual(0);
    }
    expect(coarse.value).toBeCloseTo(fine.value, 12);
    expect(Math.abs(coarse.value)).toBeLessThan(1e-6);
  });

  it('holds the value within the band of a target that jumps', () => {
    let state: FollowerState = { value: 0, velocity: 0 };
    state = followStep(state, 5, 0.016, 4, 0.2);
    expect(state.value).toBeCloseTo(4.8, 12);
    state = followStep(state, -5, 0.016, 4, 0.2);
    expect(state.value).toBeCloseTo(-4.8, 12);
    // Held at the upper edge of the band, it may only move on towards the target.
    expect(state.velocity).toBeLessThanOrEqual(0);
  });
});

describe('BoatMotion', () => {
  const still = { heading: 0, speed: 0, response: 0.25 };
  const wave = (t: number) => (x: number, z: number) =>
    1.4 * Math.sin(0.05 * x + 0.7 * t) * Math.cos(0.05 * z) + 0.3 * Math.sin(1.3 * x - 2 * t);

  it('sits exactly on the surface at the first frame, and holds its damped pose while the clock stands still', () => {
    const motion = new BoatMotion([3, -7]);
    const first = motion.update(10, still, HULL, wave(10));
    expect(first.pose).toEqual(first.target);
    let moving = first;
    for (let t = 10.016; t < 10.5; t += 0.016) moving = motion.update(t, still, HULL, wave(t));
    // A paused picture must not change when drawn again (an orbit, a share link): the boat
    // keeps its damped pose rather than jumping to its target.
    expect(moving.pose).not.toEqual(moving.target);
    const time = 11;
    const held = motion.update(time, still, HULL, wave(time));
    const frozen = motion.update(time, still, HULL, wave(time));
    expect(frozen.pose).toEqual(held.pose);
  });

  it('turns at once onto its true pose when a new heading is commanded while the clock stands still', () => {
    const motion = new BoatMotion([3, -7]);
    let t = 10;
    let state = motion.update(t, still, HULL, wave(t));
    for (let i = 0; i < 30; i++) state = motion.update((t += 0.016), still, HULL, wave(t));
    expect(state.pose).not.toEqual(state.target);
    // Drawn again unchanged, it holds its damped pose, so a paused picture does not jump.
    expect(motion.update(t, still, HULL, wave(t)).pose).toEqual(state.pose);
    // The GUI or setParams turned a paused boat: the picture shows it on its new heading, as a first frame would.
    const turned = motion.update(t, { ...still, heading: 1.5 }, HULL, wave(t));
    expect(turned.pose.heading).toBe(1.5);
    expect(turned.pose).toEqual(turned.target);
    // Drawn again with that heading, it holds.
    expect(motion.update(t, { ...still, heading: 1.5 }, HULL, wave(t)).pose).toEqual(turned.pose);
  });

  it('rebuilds itself exactly from a snapshot, held and then moving on', () => {
    const controls = { heading: 1.2, speed: 3, response: 0.25 };
    const a = new BoatMotion();
    let t = 0;
    for (let i = 0; i < 200; i++) a.update((t += 0.016), controls, HULL, wave(t));
    const snapshot = a.snapshot(t)!;
    expect(a.snapshot(t + 1)).toBeNull();
    const b = new BoatMotion();
    b.restore(snapshot, t);
    expect(b.update(t, controls, HULL, wave(t)).pose).toEqual(a.update(t, controls, HULL, wave(t)).pose);
    for (let i = 0; i < 50; i++) {
      t += 0.016;
      expect(b.update(t, controls, HULL, wave(t)).pose).toEqual(a.update(t, controls, HULL, wave(t)).pose);
    }
  });

  it('is deterministic for a sequence of times and stays in its band on a moving sea', () => {
    const run = () => {
      const motion = new BoatMotion();
      const random = seededRandom(77);
      const poses = [];
      let t = 0;
      for (let i = 0; i < 600; i++) {
        t += 0.005 + random() * 0.05;
        const { pose, target } = motion.update(t, { heading: 0.4, speed: 2, response: 0.25 }, HULL, wave(t));
        expect(Math.abs(pose.y - target.y)).toBeLessThanOrEqual(HEAVE_BAND + 1e-12);
        expect(Math.abs(pose.pitch - target.pitch)).toBeLessThanOrEqual(ANGLE_BAND + 1e-12);
        expect(Math.abs(pose.roll - target.roll)).toBeLessThanOrEqual(ANGLE_BAND + 1e-12);
        poses.push(pose);
      }
      return poses;
    };
    expect(run()).toEqual(run());
  });

  it('settles on the target of a still sea after an abrupt change, and never leaves the band meanwhile', () => {
    const motion = new BoatMotion([0, 0]);
    motion.update(0, still, HULL, () => 0);
    let state = motion.update(0.016, still, HULL, (x) => 3 + 0.3 * x);
    expect(state.pose.y).toBeCloseTo(3 - HEAVE_BAND, 12);
    for (let t = 0.032; t < 5; t += 0.016) {
      state = motion.update(t, still, HULL, (x) => 3 + 0.3 * x);
      expect(Math.abs(state.pose.roll - state.target.roll)).toBeLessThanOrEqual(ANGLE_BAND + 1e-12);
    }
    expect(state.pose.y).toBeCloseTo(3, 6);
    expect(state.pose.roll).toBeCloseTo(Math.atan(0.3), 6);
  });

  it('swings to a new heading the short way round and settles on it', () => {
    const deg = Math.PI / 180;
    const motion = new BoatMotion([0, 0]);
    motion.update(0, { ...still, heading: 350 * deg }, HULL, () => 0);
    let heading = 0;
    for (let i = 1; i <= 1500; i++) {
      heading = motion.update(i * 0.02, { ...still, heading: 10 * deg }, HULL, () => 0).pose.heading;
      expect(heading).toBeGreaterThanOrEqual(0);
      expect(heading).toBeLessThan(2 * Math.PI);
      // Through north (0), never round through south.
      expect(heading < 10.0001 * deg || heading > 349.9999 * deg).toBe(true);
    }
    expect(heading).toBeCloseTo(10 * deg, 9);
  });

  it('sails along its heading at its speed and stops at the edge of the ocean', () => {
    const motion = new BoatMotion([0, 0]);
    motion.update(0, { heading: Math.PI / 2, speed: 5, response: 0.25 }, HULL, () => 0);
    let state = motion.update(0.1, { heading: Math.PI / 2, speed: 5, response: 0.25 }, HULL, () => 0);
    expect(state.pose.x).toBeCloseTo(0.5, 12);
    expect(state.pose.z).toBeCloseTo(0, 12);
    for (let i = 2; i < 5000; i++) state = motion.update(i * 0.1, { heading: Math.PI / 2, speed: 10, response: 0.25 }, HULL, () => 0);
    expect(state.pose.x).toBe(BOAT_EXTENT);
  });

  it('sails on every frame of a slow renderer, whose frames the clock clamps to 0.1 s each', () => {
    // SimulationClock advances at most 0.1 s a frame: under SwiftShader at 1280×720 every
    // frame is that long. Summed in float64 those steps differ from 0.1 by an ulp either
    // way, so a jump threshold of exactly 0.1 s held the boat still on some of them (the
    // first at t ≈ 16 s): on a slow machine the boat barely sailed.
    const motion = new BoatMotion([0, 0]);
    const controls = { heading: Math.PI / 2, speed: 5, response: 0.25 };
    let t = 10;
    let x = motion.update(t, controls, HULL, () => 0).pose.x;
    for (let frame = 0; frame < 100; frame++) {
      const before = t;
      t += 0.1; // a 300-ms frame, clamped
      const after = motion.update(t, controls, HULL, () => 0).pose.x;
      expect(after - x, `frame ${frame}`).toBeCloseTo(5 * (t - before), 9);
      x = after;
    }
  });
});

describe('BoatMotion keeps the target pose of a paused view only while the surface is the same', () => {
  const still = { heading: 0.3, speed: 0, response: 0.25 };
  /** The boat on `model` at `time`, as BoatController floats it. */
  const float = (motion: BoatMotion, model: LiveWaveModel, time: number) =>
    motion.update(time, still, HULL, (x, z) => model.height(x, z, time), model);
  /** The target a boat that keeps nothing would take there now. */
  const fresh = (model: LiveWaveModel, time: number, at: { x: number; z: number }) =>
    targetPose((x, z) => model.height(x, z, time), at.x, at.z, still.heading, HULL);

  it('samples the surface once for a paused view drawn again, and again for another time, place or model', () => {
    const model = new SeedWaveModel(defaultParams());
    let samples = 0;
    const motion = new BoatMotion([3, -7]);
    const heightAt = (t: number) => (x: number, z: number) => (samples++, model.height(x, z, t));
    motion.update(10, still, HULL, heightAt(10), model);
    expect(samples).toBe(5);
    motion.update(10, still, HULL, heightAt(10), model);
    motion.update(10, still, HULL, heightAt(10), model);
    expect(samples).toBe(5);
    motion.update(10.016, still, HULL, heightAt(10.016), model);
    expect(samples).toBe(10);
    motion.update(10.016, still, HULL, heightAt(10.016), new SeedWaveModel(defaultParams()));
    expect(samples).toBe(15);
    // Without a surface key nothing is kept (scripts, tests).
    motion.update(10.016, still, HULL, heightAt(10.016));
    expect(samples).toBe(20);
  });

  // Each case changes the surface at a paused time; the kept pose must follow. Negative
  // controls: a model whose setParams (seed, gerstner) or whose adopted or computed fields
  // (fft) leave surfaceRevision unchanged fails here, as does a cache that ignores it.
  it.each([
    ['the seed sea', () => new SeedWaveModel(defaultParams()), { swellAmplitude: 2.5 }],
    ['the Gerstner sea', () => new GerstnerLiveModel(defaultParams()), { windSpeed: 16 }],
  ] as const)('%s: new parameters at the same time', (_name, makeModel, change) => {
    const model = makeModel();
    const motion = new BoatMotion([3, -7]);
    const before = float(motion, model, 10).target;
    model.setParams({ ...defaultParams(), ...change });
    const after = float(motion, model, 10).target;
    expect(after).toEqual(fresh(model, 10, after));
    expect(Math.abs(after.y - before.y)).toBeGreaterThan(1e-3);
  });

  it("the FFT sea: the Worker's fields for the paused time arrive after a lagged frame", () => {
    const params = { ...defaultParams(), waves: 'fft' as const, fftSize: '64' as const, windSpeed: 12 };
    const model = new FftWaveModel(params);
    model.attachSource({ request: () => {}, dispose: () => {} });
    const motion = new BoatMotion([3, -7]);
    float(motion, model, 10); // a jump: computed at once
    const lagged = float(motion, model, 10.016).target; // playing: the fields of t = 10
    expect(float(motion, model, 10.016).target).toBe(lagged); // paused there: kept
    const worker = new FftOcean(model.sea);
    worker.setTime(10.016);
    model.receive(
      model.sea,
      10.016,
      worker.fields.map((f) => ({ displacement: f.displacement.slice(), derivatives: f.derivatives.slice() })),
    );
    const after = float(motion, model, 10.016).target;
    expect(after).toEqual(fresh(model, 10.016, after));
    expect(Math.abs(after.y - lagged.y)).toBeGreaterThan(1e-4);
    // Fields computed on the calling thread for the paused time: the next frame lags again,
    // and there the API's sampleSurface (always exact) computes that time's fields.
    const laggedAgain = float(motion, model, 10.033).target;
    expect(float(motion, model, 10.033).target).toBe(laggedAgain);
    model.sample(0, 0, 10.033);
    const exact = float(motion, model, 10.033).target;
    expect(exact).toEqual(fresh(model, 10.033, exact));
    expect(Math.abs(exact.y - laggedAgain.y)).toBeGreaterThan(1e-4);
  });
});
