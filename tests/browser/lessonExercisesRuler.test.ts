import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { answer, openLesson } from './lessonExerciseStudent';
import { crestRadii, stoneGuideReach } from '../../src/sim/iwave/cauchyPoissonRings';

/**
 * A scripted student does the ruler exercises: runs the sea to the moment the card asks for,
 * finds the crests (or the boat) by looking at the heights, drags the sea tools' ruler between
 * them with the mouse, reads its label, types it, presses Check and is told "Within
 * tolerance"; the usual slip is told "Not yet".
 */
const harness = useHarness();

/** Runs the paused clock from `start` to `to` in steps of `step` s, a frame drawn at each (the field and the boat advance frame by frame). */
async function runTo(page: Page, start: number, to: number, step: number): Promise<void> {
  await page.evaluate(
    async (start, end, dt) => {
      for (let t = start + dt; t <= end + 1e-9; t += dt) {
        window.oceano.setTime(t);
        window.oceano.renderFrame();
      }
      window.oceano.setTime(end);
      window.oceano.renderFrame();
      // The interactive field's read-back, a frame or two behind.
      for (let frame = 0; frame < 4; frame++) {
        window.oceano.renderFrame();
        await new Promise((r) => setTimeout(r, 100));
      }
    },
    start,
    to,
    step,
  );
}

function pixelOf(page: Page, x: number, y: number, z: number): Promise<[number, number]> {
  return page.evaluate(
    (px, py, pz) => {
      const camera = window.oceano.three.camera;
      camera.updateMatrixWorld();
      const v = [px, py, pz, 1];
      const view = camera.matrixWorldInverse.elements;
      const proj = camera.projectionMatrix.elements;
      const mul = (m: ArrayLike<number>, a: number[]) =>
        [0, 1, 2, 3].map((r) => m[r] * a[0] + m[4 + r] * a[1] + m[8 + r] * a[2] + m[12 + r] * a[3]);
      const c = mul(proj, mul(view, v));
      const rect = window.oceano.three.renderer.domElement.getBoundingClientRect();
      return [rect.left + ((c[0] / c[3] + 1) / 2) * rect.width, rect.top + ((1 - c[1] / c[3]) / 2) * rect.height] as [number, number];
    },
    x,
    y,
    z,
  );
}

/** Heights along the line from (x, z) in direction (dx, dz), every 0.1 m from `from` to `to` metres. */
function profile(page: Page, x: number, z: number, dx: number, dz: number, from: number, to: number): Promise<number[]> {
  return page.evaluate(
    (x, z, dx, dz, from, to) =>
      Array.from(
        { length: Math.round((to - from) * 10) + 1 },
        (_, i) => window.oceano.sampleSurface(x + dx * (from + i * 0.1), z + dz * (from + i * 0.1)).height,
      ),
    x,
    z,
    dx,
    dz,
    from,
    to,
  );
}

/** Distances (m) of the crests, local maxima above the calm water, in a profile starting at `from`. */
function crestsOf(heights: number[], from: number): number[] {
  const out: number[] = [];
  for (let i = 1; i < heights.length - 1; i++)
    if (heights[i] > heights[i - 1] && heights[i] >= heights[i + 1] && heights[i] > 0) out.push(from + i * 0.1);
  return out;
}

let toolsOpen = false;
/** Opens the sea tools, picks the ruler and drags it from world a to world b on the sea; answers the ruler's label. */
async function rule(page: Page, a: [number, number, number], b: [number, number, number]): Promise<string> {
  if (!toolsOpen) {
    await page.evaluate(() =>
      Array.from(document.querySelectorAll<HTMLButtonElement>('.lil-gui button'))
        .find((el) => /Sea tools/.test(el.textContent ?? ''))!
        .click(),
    );
    await page.waitForSelector('.oceano-sea-tools:not([hidden])');
    await page.click('.oceano-sea-tools input[value="ruler"]');
    toolsOpen = true;
  }
  const pa = await pixelOf(page, ...a);
  const pb = await pixelOf(page, ...b);
  await page.mouse.move(...pa);
  await page.mouse.down();
  await page.mouse.move(...pb, { steps: 4 });
  await page.mouse.up();
  await page.evaluate(() => window.oceano.renderFrame());
  return page.$eval('.oceano-ruler-label', (el) => el.textContent ?? '');
}

describe('ruler exercises, done with the ruler', () => {
  // iwave-stone, iwave-compare, group-velocity, wake-turn.
  it('four cards: the ruler’s readings are within tolerance; the slips are "Not yet"', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=0&lesson=iwave-stone', 1366, 768);
    await page.waitForSelector('.lil-gui.lil-root');
    toolsOpen = false;

    // iwave-stone: 12 s after the stone, from the outermost ring's crest to the next crest inward.
    await openLesson(page, 'iwave-stone');
    await page.evaluate(() => {
      window.oceano.pause();
      window.oceano.setTime(0);
      window.oceano.renderFrame();
    });
    await openLesson(page, 'iwave-stone');
    await runTo(page, 0, 12, 2);
    const [sx, sz] = [-20, -20];
    // Toward the camera (+z): the student looks along the rings' radius nearest to them.
    const heights = await profile(page, sx, sz, 0, 1, 4, 40);
    const crests = crestsOf(heights, 4);
    const ring = crestRadii(12, stoneGuideReach())[0];
    console.log(`iwave-stone: outermost ring at ${ring.toFixed(2)} m, crests at ${crests.map((r) => r.toFixed(1)).join(', ')} m`);
    const outer = crests.reduce((best, r) => (Math.abs(r - ring) < Math.abs(best - ring) ? r : best));
    const inner = crests.filter((r) => r < outer).at(-1)!;
    const spacingLabel = await rule(page, [sx, 0, sz + outer], [sx, 0, sz + inner]);
    const spacing = Number.parseFloat(spacingLabel).toFixed(2);
    const stoneRight = await answer(page, spacing);
    console.log(`iwave-stone: ruler ${spacingLabel}; ${stoneRight.text}`);
    expect(stoneRight.verdict, stoneRight.text).toBe('within');
    expect((await answer(page, (2 * Number(spacing)).toFixed(2))).verdict).toBe('not-yet');

    // iwave-compare: the wave equation's ring (right-hand stone), 8 s after it fell.
    await openLesson(page, 'iwave-compare');
    await runTo(page, 12, 20, 2);
    const [wx, wz] = [-32, -20];
    const ringHeights = await profile(page, wx, wz, 0, 1, 4, 30);
    const top = ringHeights.indexOf(Math.max(...ringHeights));
    const ringRadius = 4 + top * 0.1;
    const ringLabel = await rule(page, [wx, 0, wz], [wx, 0, wz + ringRadius]);
    const ringRight = await answer(page, Number.parseFloat(ringLabel).toFixed(2));
    console.log(`iwave-compare: ring crest at ${ringRadius.toFixed(1)} m, ruler ${ringLabel}; ${ringRight.text}`);
    expect(ringRight.verdict, ringRight.text).toBe('within');
    // Slip: the ring read, then the clock run on another 2 s before Check.
    await runTo(page, 20, 22, 2);
    expect((await answer(page, Number.parseFloat(ringLabel).toFixed(2))).verdict).toBe('not-yet');

    // group-velocity: the same stone's outermost marked crest, 12 s after it fell, is where its group has run.
    // A minute on, as a student reaching this card later: the jump past the field's 10 s catch-up restarts it calm, so
    // the first stone's waves, at the same spot, are gone.
    await page.evaluate(() => {
      window.oceano.setTime(90);
      window.oceano.renderFrame();
    });
    await openLesson(page, 'group-velocity');
    await runTo(page, 90, 102, 2);
    const groupCrests = crestsOf(await profile(page, sx, sz, 0, 1, 4, 40), 4);
    const groupRing = crestRadii(12, stoneGuideReach())[0];
    const groupCrest = groupCrests.reduce((best, r) => (Math.abs(r - groupRing) < Math.abs(best - groupRing) ? r : best));
    const groupLabel = await rule(page, [sx, 0, sz], [sx, 0, sz + groupCrest]);
    const groupRight = await answer(page, Number.parseFloat(groupLabel).toFixed(2));
    console.log(`group-velocity: crests at ${groupCrests.map((r) => r.toFixed(1)).join(', ')} m, ruler ${groupLabel}; ${groupRight.text}`);
    expect(groupRight.verdict, groupRight.text).toBe('within');
    // Slip: the phase speed's distance c t, twice the group's.
    expect((await answer(page, (2 * Number.parseFloat(groupLabel)).toFixed(2))).verdict).toBe('not-yet');

    // wake-turn: the rudder held over only turns the boat while the clock plays (it steers frame by frame), so the
    // student plays it, at the card's fastest turn to be quick: 20°/s, half a turn in 9 s. Where the boat was when
    // Play was pressed, and where it is when its heading has reversed and the student pauses.
    await openLesson(page, 'wake-turn');
    await page.evaluate(() => window.oceano.setParams({ boatTurnRate: 20 }));
    const start = await page.evaluate(() => window.oceano.boat().position);
    await page.evaluate(() => window.oceano.play());
    await page.waitForFunction(() => Math.abs((window.oceano.boat().heading * 180) / Math.PI - 90) < 3, { timeout: 240_000, polling: 20 });
    await page.evaluate(() => window.oceano.pause());
    const end = await page.evaluate(() => window.oceano.boat());
    console.log(
      `wake-turn: boat from (${start[0].toFixed(1)}, ${start[2].toFixed(1)}) to (${end.position[0].toFixed(1)}, ${end.position[2].toFixed(1)}), heading ${((end.heading * 180) / Math.PI).toFixed(1)}°`,
    );
    // The student pulls the view back over the whole half circle.
    const [mx, mz] = [(start[0] + end.position[0]) / 2, (start[2] + end.position[2]) / 2];
    await page.evaluate(
      (x, z) => {
        window.oceano.setCamera({ position: [x, 220, z + 60], target: [x, 0, z] });
        window.oceano.renderFrame();
      },
      mx,
      mz,
    );
    const diameterLabel = await rule(page, [start[0], 0, start[2]], [end.position[0], 0, end.position[2]]);
    const radius = (Number.parseFloat(diameterLabel) / 2).toFixed(1);
    const turnRight = await answer(page, radius);
    console.log(`wake-turn: ruler ${diameterLabel} across, R = ${radius} m; ${turnRight.text}`);
    expect(turnRight.verdict, turnRight.text).toBe('within');
    // Slip: the diameter typed for the radius.
    expect((await answer(page, Number.parseFloat(diameterLabel).toFixed(1))).verdict).toBe('not-yet');

    expect(consoleErrors).toEqual([]);
    await page.close();
  }, 1_200_000);
});
