import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { describeDifference, diffPngs, measureDifference, withinTolerance } from './imageCompare';
import { useHarness } from './useHarness';
import { PARITY_LIMITS } from './parity';
import { seededRandom } from '../../src/sim/noise/integerHash';

/**
 * The boat's Kelvin wake in the running app: the GPU probe runs the active model's chunk and
 * adds shaders/wake.glsl exactly as ocean.vert does (at the displaced point q = p + Dₕ(p));
 * sampleSurface(q) must give the same height and normal from the CPU twin (the model's sample
 * plus BoatWake's wake from the same track). The boat holds a turn, so the track is curved;
 * each time is a jump, so the track is the deterministic replay (src/sim/wake/boatWake.ts). Most
 * points lie within 150 m of the boat, where the wake is; the rest anywhere out to 3 km.
 *
 * Controls (each must break the limits): the CPU twin without the wake, and on a calm sea
 * (only the wake moves) the CPU one frame (1/60 s) late.
 *
 * Measured on SwiftShader: seed |Δh| 1.13e-5 m, |Δn| 2.17e-5 (limits 3e-5, 4e-5, those of
 * surfaceParity); gerstner |Δh| 1.56e-5 m, |Δn| 3.5e-6 (limits 1e-4, 1e-3, those of
 * gerstnerApp); the wake reaches 0.45 and 0.63 m at these points. Controls: without the wake
 * 0.45 m / 0.39 and 0.63 m / 0.29; one frame late on a calm sea 8.1e-3 m.
 */
const PARITY_SEED = 20261123;
const TIMES = [0, 37.25, 4321.5];
const NEAR_POINTS = 96;
const FAR_POINTS = 32;
const BOAT = 'wake=1&boatSpeed=4&boatHeading=270&boatTurnRate=3';

const harness = useHarness();

type Cases = { t: number; points: [number, number][] }[];
type Fault = 'none' | 'noWakeOnCpu' | 'cpuFrameLate';

function cases(): Cases {
  const random = seededRandom(PARITY_SEED);
  const near = (): [number, number] => [Math.fround(7 + (random() * 2 - 1) * 150), Math.fround(-5 + (random() * 2 - 1) * 150)];
  const far = (): [number, number] => [Math.fround((random() * 2 - 1) * 3000), Math.fround((random() * 2 - 1) * 3000)];
  return TIMES.map((t) => ({ t, points: [...Array.from({ length: NEAR_POINTS }, near), ...Array.from({ length: FAR_POINTS }, far)] }));
}

function worst(page: Page, cases: Cases, fault: Fault) {
  return page.evaluate(
    async (cases, fault) => {
      const o = window.oceano;
      o.pause();
      let height = 0;
      let normal = 0;
      let wake = 0;
      for (const { t, points } of cases) {
        o.setTime(t);
        o.renderFrame();
        const gpu = await o.probeGpu(points, t);
        if (fault === 'noWakeOnCpu') o.setParams({ wake: false });
        if (fault === 'cpuFrameLate') {
          o.setTime(t + 1 / 60);
          o.renderFrame();
        }
        points.forEach(([x, z], i) => {
          const d = gpu[i].displacement;
          const cpu = o.sampleSurface(x + d[0], z + d[2]);
          height = Math.max(height, Math.abs(cpu.height - d[1]));
          for (let c = 0; c < 3; c++) normal = Math.max(normal, Math.abs(cpu.normal[c] - gpu[i].normal[c]));
        });
        if (fault === 'noWakeOnCpu') o.setParams({ wake: true });
        // How big the wake itself is at these points (the CPU's sum minus the waves alone), so the test shows it was there.
        if (fault === 'none') {
          o.setParams({ wake: false });
          const bare = points.map(([x, z], i) => o.sampleSurface(x + gpu[i].displacement[0], z + gpu[i].displacement[2]).height);
          o.setParams({ wake: true });
          points.forEach(
            ([x, z], i) =>
              (wake = Math.max(wake, Math.abs(o.sampleSurface(x + gpu[i].displacement[0], z + gpu[i].displacement[2]).height - bare[i]))),
          );
        }
      }
      return { height, normal, wake };
    },
    cases,
    fault,
  );
}

describe('the Kelvin wake: CPU twin vs the drawn mesh', () => {
  // TIMES.length × (NEAR_POINTS + FAR_POINTS) points.
  it.each([
    { query: `seed=3&t=0&${BOAT}`, height: PARITY_LIMITS.defaults.height, normal: PARITY_LIMITS.defaults.normal, late: true },
    { query: `waves=gerstner&seed=3&t=0&${BOAT}`, height: 1e-4, normal: 1e-3, late: false },
  ])(
    "agrees on every point with the wake on, within the model's own limits; the controls do not: $query",
    async ({ query, height, normal, late }) => {
      const { page, consoleErrors } = await openOcean(harness, query, 320, 180);
      const ok = await worst(page, cases(), 'none');
      const control = await worst(page, cases(), 'noWakeOnCpu');
      console.log(
        `[oceano] wake parity (${query}): |Δh| ${ok.height.toExponential(2)} m, |Δn| ${ok.normal.toExponential(2)} (largest wake ${ok.wake.toExponential(2)} m); ` +
          `control, CPU without wake: |Δh| ${control.height.toExponential(2)} m, |Δn| ${control.normal.toExponential(2)}`,
      );
      expect(consoleErrors).toEqual([]);
      expect(ok.wake).toBeGreaterThan(0.05);
      expect(ok.height).toBeLessThan(height);
      expect(ok.normal).toBeLessThan(normal);
      expect(control.height).toBeGreaterThan(height);
      expect(control.normal).toBeGreaterThan(normal);
      if (late) {
        // The boat floats on the waves without its own wake: its undamped pose is the same with
        // the wake off, while the surface drawn under its centre is not (the control).
        const boat = await page.evaluate(() => {
          const o = window.oceano;
          o.setTime(37.25);
          o.renderFrame();
          const on = o.boat().target;
          const drawn = o.sampleSurface(on.position[0], on.position[2]).height;
          o.setParams({ wake: false });
          o.renderFrame();
          const off = o.boat().target;
          const bare = o.sampleSurface(on.position[0], on.position[2]).height;
          o.setParams({ wake: true });
          return {
            dy: Math.abs(on.position[1] - off.position[1]),
            dPitch: Math.abs(on.pitch - off.pitch),
            wakeUnderBoat: Math.abs(drawn - bare),
          };
        });
        console.log(
          `[oceano] the boat with and without its own wake: |Δy| ${boat.dy} m, |Δpitch| ${boat.dPitch}; the wake under it ${boat.wakeUnderBoat.toExponential(2)} m`,
        );
        expect(boat.dy).toBe(0);
        expect(boat.dPitch).toBe(0);
        expect(boat.wakeUnderBoat).toBeGreaterThan(0.01);
        // A calm sea, so only the wake changes in the frame the CPU is late by.
        await page.evaluate(() => window.oceano.setParams({ swellAmplitude: 0, rippleStrength: 0 }));
        const frameLate = await worst(page, cases().slice(1, 2), 'cpuFrameLate');
        console.log(
          `[oceano] wake parity control, CPU 1/60 s late on a calm sea: |Δh| ${frameLate.height.toExponential(2)} m, |Δn| ${frameLate.normal.toExponential(2)}`,
        );
        expect(frameLate.height).toBeGreaterThan(height);
      }
      await page.close();
    },
  );

  // Control: without its track it shows the replay instead.
  it('a share link made while sailing and steering reopens on the same wake, pixel for pixel', async () => {
    const { page } = await openOcean(harness, 'preset=wake-turn', 320, 180);
    const url = await page.evaluate(async () => {
      const o = window.oceano;
      const wait = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));
      o.play();
      await wait(1500);
      // Steer the other way: the track bends back, which no replay of the present course makes.
      o.setParams({ boatTurnRate: -12 });
      await wait(2500);
      o.pause();
      o.renderFrame();
      return o.shareUrl();
    });
    expect(url).toMatch(/[?&]wakeTrack=/);
    const original = await canvasPng(page);
    await page.close();
    const query = url.slice(url.indexOf('?') + 1);
    const reopened = await openOcean(harness, query, 320, 180);
    expect(await reopened.page.evaluate(() => window.oceano.notices())).toEqual([]);
    const same = diffPngs(original, await canvasPng(reopened.page), 0).differentPixels;
    await reopened.page.close();
    const replay = await openOcean(harness, query.replace(/&?wakeTrack=[^&]*/, ''), 320, 180);
    const replayed = measureDifference(original, await canvasPng(replay.page));
    await replay.page.close();
    console.log(`[oceano] wake share link: reopened, ${same} pixels differ; without its track ${describeDifference(replayed)}`);
    expect(same).toBe(0);
    expect(withinTolerance(replayed), describeDifference(replayed)).toBe(false);
  });
});
