import { describe, expect, it } from 'vitest';
import { IWaveGrid, IWAVE_SPONGE } from '../../../../src/sim/iwave/iwaveGrid';
import { fittedVerticalDerivativeKernel } from '../../../../src/sim/iwave/verticalDerivativeKernel';
import { besideHull, hullCovers, hullEarlier, hullSources, type MovingHull } from '../../../../src/sim/iwave/movingHull';
import { analyticWakeWeight, handOverDistance, handOverWeights, HAND_OVER_WIDTH } from '../../../../src/sim/iwave/kelvinHandOver';
import { targetPose } from '../../../../src/sim/boat/boatPose';
import { replayedPosition } from '../../../../src/sim/wake/boatWake';
import { VOLUME_PER_LENGTH_CUBED } from '../../../../src/sim/wake/kelvinWake';

/** The boat in the interactive field (src/sim/iwave/movingHull.ts) and its hand-over to the analytic wake, on the CPU solver. */
const spacing = 0.5;
const kernel = fittedVerticalDerivativeKernel();
const boat = (x: number, z: number, heading: number, speed = 0): MovingHull => ({
  x,
  z,
  heading,
  speed,
  length: 8,
  beam: 2.6,
  strength: 1,
});

describe('the hull in the field', () => {
  // Planted fault: the hull out of reach sends nothing.
  it("reflects a wave that meets it: on the stone's side, what differs from open water came off the hull", () => {
    // A stone 6 m west of a boat lying broadside to it (heading 0: its length along z), 10 s on.
    const run = (hull: MovingHull | null) => {
      const grid = new IWaveGrid({ n: 128, spacing, kernel, sponge: IWAVE_SPONGE });
      grid.hull = hull;
      grid.disturb({ x: -6, z: 0, radius: 1, height: 0.3 });
      for (let s = 0; s < 300; s++) grid.step(1 / 30);
      return grid;
    };
    const open = run(null);
    const backFrom = (grid: IWaveGrid) => {
      let back = 0;
      let free = 0;
      // On the stone's side of the hull (x from −30 to −2 m): what differs from open water there came off the hull.
      for (let j = 0; j < grid.n; j++) {
        for (let i = 0; i < grid.n; i++) {
          const c = j * grid.n + i;
          if (grid.texelX(i) < -30 || grid.texelX(i) > -2 || Math.abs(grid.texelZ(j)) > 15) continue;
          back = Math.max(back, Math.abs(grid.height[c] - open.height[c]));
          free = Math.max(free, Math.abs(open.height[c]));
        }
      }
      return { back, free };
    };
    const hulled = run(boat(0, 0, 0));
    const { back, free } = backFrom(hulled);
    let dry = 0;
    for (let j = 0; j < hulled.n; j++)
      for (let i = 0; i < hulled.n; i++)
        if (hullCovers(boat(0, 0, 0), hulled.texelX(i), hulled.texelZ(j))) dry = Math.max(dry, Math.abs(hulled.height[j * hulled.n + i]));
    console.log(
      `Waves sent back by the hull, on the stone's side: ${back.toFixed(4)} m, against the free ring's ${free.toFixed(4)} m there (${((100 * back) / free).toFixed(0)} %)`,
    );
    expect(dry).toBe(0);
    expect(back).toBeGreaterThan(0.1 * free);
    // Planted fault: the same hull 40 m east, out of the waves' reach by then.
    expect(backFrom(run(boat(40, 0, 0))).back).toBeLessThan(0.1 * free);
  }, 120_000);

  it('pushes U·V/L cubic metres a second aside at the bow and lets as much back at the stern: the volume is kept', () => {
    const hull = boat(0.3, -0.2, 0.7, 4);
    const [bow, stern] = hullSources(hull);
    expect(bow.rate).toBeCloseTo(-stern.rate, 12);
    // One step from calm water: the bow's bump alone, summed over the texels, is the flux × dt.
    const grid = new IWaveGrid({ n: 96, spacing, kernel });
    grid.hull = { ...hull };
    grid.step(1 / 60);
    let ahead = 0;
    let total = 0;
    const [fx, fz] = [Math.sin(0.7), -Math.cos(0.7)];
    for (let j = 0; j < grid.n; j++) {
      for (let i = 0; i < grid.n; i++) {
        const h = grid.height[j * grid.n + i] * spacing * spacing;
        total += h;
        if ((grid.texelX(i) - hull.x) * fx + (grid.texelZ(j) - hull.z) * fz > 0) ahead += h;
      }
    }
    const flux = 4 * VOLUME_PER_LENGTH_CUBED * 8 * 8;
    console.log(
      `One step at 4 m/s: ${ahead.toExponential(3)} m³ ahead of the hull's centre, flux × dt ${(flux / 60).toExponential(3)} m³, sum ${total.toExponential(2)} m³`,
    );
    expect(Math.abs(total)).toBeLessThan(1e-3 * ahead);
    // The footprint cuts the bump's tail inside the hull: within 10 % of the whole.
    expect(ahead / (flux / 60)).toBeGreaterThan(0.9);
    expect(ahead / (flux / 60)).toBeLessThan(1.01);
  });

  // On a turn, as the wake's replay integrates it.
  it('puts the hull where it was a moment ago on its present course, straight and on a steady turn', () => {
    const now = boat(10, -4, 1.1, 5);
    const straight = hullEarlier(now, 0, 2);
    expect(straight.x).toBeCloseTo(10 - 5 * 2 * Math.sin(1.1), 10);
    expect(straight.z).toBeCloseTo(-4 + 5 * 2 * Math.cos(1.1), 10);
    const turnRate = 0.1;
    const turning = hullEarlier(now, turnRate, 3);
    const [x, z] = replayedPosition({ x: 10, z: -4, heading: 1.1, speed: 5, turnRate }, 3);
    expect(turning.x).toBeCloseTo(x, 3);
    expect(turning.z).toBeCloseTo(z, 3);
    expect(turning.heading).toBeCloseTo(1.1 - 0.3, 12);
  });

  // The field under the hull (held at 0) cannot (planted fault).
  it("lets the boat feel the water beside it: a stone's waves lift its target pose", () => {
    const grid = new IWaveGrid({ n: 96, spacing, kernel, sponge: IWAVE_SPONGE });
    const hull = boat(0, 0, 0.3);
    grid.hull = hull;
    grid.disturb({ x: 6, z: 2, radius: 1.2, height: 0.4 });
    for (let s = 0; s < 40; s++) grid.step(1 / 30);
    const field = (x: number, z: number) => grid.sample(x, z);
    const beside = besideHull(field, hull, 2 * spacing);
    const pose = targetPose(beside, hull.x, hull.z, hull.heading, hull);
    const under = targetPose(field, hull.x, hull.z, hull.heading, hull);
    console.log(
      `Heave from the field beside the hull: ${pose.y.toFixed(4)} m, roll ${pose.roll.toFixed(4)} rad; read under the hull: ${under.y} m`,
    );
    expect(under.y).toBe(0);
    expect(Math.abs(pose.y)).toBeGreaterThan(1e-3);
    expect(Math.abs(pose.roll)).toBeGreaterThan(1e-4);
    // Away from the hull, besideHull reads the field where asked.
    expect(beside(20, -3)).toBe(field(20, -3));
  });
});

describe('the hand-over to the analytic Kelvin wake', () => {
  // 2πU²/g is the transverse wavelength (Kelvin 1887).
  it('starts at D = max(2 L, 2πU²/g) and blends over 8 m, the two weights summing to 1', () => {
    expect(handOverDistance(4, 8)).toBe(16);
    expect(handOverDistance(6, 8)).toBeCloseTo((2 * Math.PI * 36) / 9.81, 12);
    expect((2 * Math.PI * 36) / 9.81).toBeCloseTo(23.06, 2);
    expect(analyticWakeWeight(10, 16)).toBe(0);
    expect(analyticWakeWeight(16, 16)).toBe(0);
    expect(analyticWakeWeight(16 + HAND_OVER_WIDTH / 2, 16)).toBeCloseTo(0.5, 12);
    expect(analyticWakeWeight(30, 16)).toBe(1);
    for (const d of [0, 17, 19.5, 22, 40]) {
      const [wake, field] = handOverWeights({ x: 3, z: -1, distance: 16 }, 3 + d, -1);
      expect(wake + field).toBe(1);
    }
    expect(handOverWeights(null, 100, 100)).toEqual([1, 1]);
  });
});
