import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { answer, openLesson } from './lessonExerciseStudent';
import { forwardOf } from '../../src/sim/boat/boatPose';

/**
 * A scripted student does each lesson's measurement with the tools, as a user would: ticks the
 * physics panel in the control panel and reads its "measured" column, or drags the sea tools'
 * ruler over the wake and reads its label; types the value, presses Check, and is told
 * "Within tolerance". A wrong value (the usual slip for each) is told "Not yet".
 */
const harness = useHarness();

/** Ticks the control panel's "Physics panel" box (unless ticked) and reads the row `row` of its "measured" column. */
async function physicsReading(page: Page, row: RegExp): Promise<string> {
  await page.evaluate(() => {
    const names = Array.from(document.querySelectorAll('.lil-gui .lil-name, .lil-gui .name'));
    const name = names.find((n) => /^Physics panel/.test(n.textContent ?? ''));
    if (!name) throw new Error(`no Physics panel box among: ${names.map((n) => n.textContent).join(' | ')}`);
    const box = name.parentElement!.querySelector<HTMLInputElement>('input[type="checkbox"]')!;
    // Open since an earlier lesson (or by this lesson's own physics=1), the panel measures the new sea by itself.
    if (!box.checked) box.click();
  });
  // The estimators run on the CPU twin: 16 points × 512 times, 10 to 40 s on a loaded 2-core machine.
  await page.waitForSelector('.oceano-physics table', { timeout: 120_000 });
  return page.$$eval(
    '.oceano-physics table tr',
    (rows, source) => {
      const match = rows.find((tr) => new RegExp(source).test(tr.cells[0]?.textContent ?? ''))!;
      return match.cells[1].textContent ?? '';
    },
    row.source,
  );
}

/** Pixel of world point (x, y, z) on the canvas, through the app's own camera. */
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

describe('measurement exercises, done with the tools', () => {
  it('the physics panel’s Hs and Tp, typed in, are within tolerance; the usual slips are "Not yet"', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=100&lesson=fft-calm', 1366, 768);
    await page.waitForSelector('.lil-gui.lil-root');
    const cases: [string, RegExp, number][] = [
      // Slips: twice Hs (crest to trough for a height), Tz for Tp (0.71 Tp).
      ['fft-calm', /^Hs = 4σ/, 2],
      ['fft-fresh-breeze', /^Peak period Tp/, 0.71],
      ['fft-short-fetch', /^Peak period Tp/, 0.71],
      ['fft-gale', /^Hs = 4σ/, 2],
      ['physics-panel', /^Hs = 4σ/, 2],
    ];
    for (const [lesson, row, slip] of cases) {
      await openLesson(page, lesson);
      await page.evaluate(() => window.oceano.pause());
      const read = await physicsReading(page, row);
      const right = await answer(page, read);
      console.log(`${lesson}: read ${read}, ${right.text}`);
      expect(right.verdict, `${lesson}: ${right.text}`).toBe('within');
      expect(right.text).toMatch(/^Within tolerance/);
      const wrong = await answer(page, (Number(read) * slip).toFixed(2));
      expect(wrong.verdict, `${lesson}: ${wrong.text}`).toBe('not-yet');
      expect(wrong.text).toMatch(/^Not yet/);
    }
    expect(consoleErrors).toEqual([]);
    await page.close();
    // Five measurements on the CPU twin: 86 s in all on a loaded 2-core machine.
  }, 600_000);

  // The ruler over three transverse crests behind the boat gives 2πU²/g within 10 %; half of it is "Not yet".
  it('kelvin-wake: the ruler over the transverse crests gives 2πU²/g; half of it is "Not yet"', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=0&lesson=kelvin-wake', 1366, 768);
    await page.waitForSelector('.oceano-lesson-exercise');
    await page.evaluate(() => window.oceano.pause());
    // 20 s of the boat's run, drawn frame by frame: the wake builds behind it.
    await page.evaluate(() => {
      for (let i = 1; i <= 40; i++) {
        window.oceano.setTime(i * 0.5);
        window.oceano.renderFrame();
      }
    });
    const boat = await page.evaluate(() => window.oceano.boat());
    const [fx, fz] = forwardOf(boat.heading);
    const [bx, , bz] = boat.position;
    // The student's eye on the wake: heights along the track behind the boat, and the crests among them.
    const profile = await page.evaluate(
      (bx, bz, dx, dz) =>
        Array.from({ length: 601 }, (_, i) => {
          const s = 8 + i * 0.1;
          return window.oceano.sampleSurface(bx - dx * s, bz - dz * s).height;
        }),
      bx,
      bz,
      fx,
      fz,
    );
    const crests: number[] = [];
    for (let i = 1; i < profile.length - 1; i++)
      if (profile[i] > profile[i - 1] && profile[i] >= profile[i + 1] && profile[i] > 0) crests.push(8 + i * 0.1);
    console.log(`kelvin-wake: crests behind the boat at ${crests.map((s) => s.toFixed(1)).join(', ')} m`);
    expect(crests.length).toBeGreaterThanOrEqual(4);
    const [s0, s3] = [crests[0], crests[3]];
    const a = await pixelOf(page, bx - fx * s0, 0, bz - fz * s0);
    const b = await pixelOf(page, bx - fx * s3, 0, bz - fz * s3);

    await page.evaluate(() =>
      Array.from(document.querySelectorAll<HTMLButtonElement>('.lil-gui button'))
        .find((el) => /Sea tools/.test(el.textContent ?? ''))!
        .click(),
    );
    await page.waitForSelector('.oceano-sea-tools:not([hidden])');
    await page.click('.oceano-sea-tools input[value="ruler"]');
    await page.mouse.move(...a);
    await page.mouse.down();
    await page.mouse.move(...b, { steps: 4 });
    await page.mouse.up();
    await page.evaluate(() => window.oceano.renderFrame());
    const label = await page.$eval('.oceano-ruler-label', (el) => el.textContent ?? '');
    const lambda = (Number.parseFloat(label) / 3).toFixed(2);
    const right = await answer(page, lambda);
    console.log(`kelvin-wake: ruler ${label} over three waves, λ = ${lambda} m; ${right.text}`);
    expect(right.verdict, right.text).toBe('within');
    const wrong = await answer(page, (Number(lambda) / 2).toFixed(2));
    expect(wrong.verdict).toBe('not-yet');
    expect(consoleErrors).toEqual([]);
    await page.close();
  }, 300_000);

  it('oceano.lessons() says which lessons have an exercise; a card without one shows none', async () => {
    const { page } = await openOcean(harness, 'lesson=fresnel', 640, 360);
    await page.evaluate(() => window.oceano.ready);
    const lessons = await page.evaluate(() => window.oceano.lessons());
    expect(lessons.filter((l) => l.exercise).map((l) => l.id)).toEqual([
      'sun-glint',
      'fft-calm',
      'fft-fresh-breeze',
      'fft-short-fetch',
      'fft-gale',
      'gerstner-gentle',
      'physics-panel',
      'kelvin-wake',
      'wake-turn',
      'iwave-stone',
      'iwave-compare',
      'airy-waves',
      'group-velocity',
      'spectra-compared',
      'fft-transform',
    ]);
    await page.waitForSelector('.oceano-lesson-card[data-lesson="fresnel"]');
    expect(await page.$('.oceano-lesson-exercise')).toBeNull();
    await page.close();
  });
});

describe.runIf(process.env.OCEANO_SHOTS)('screenshots of an exercise card (OCEANO_SHOTS=folder)', () => {
  // The answer typed is the ruler's 30.72 m over three waves, as the test above read it.
  it('kelvin-wake with a typed answer: laptop in English, phone in Spanish', async () => {
    for (const [width, height, lang] of [
      [1366, 768, 'en'],
      [390, 844, 'es'],
    ] as const) {
      const { page } = await openOcean(harness, `t=20&lesson=kelvin-wake&lang=${lang}`, width, height);
      await page.waitForSelector('.oceano-lesson-exercise');
      await page.evaluate(() => window.oceano.pause());
      await answer(page, lang === 'es' ? '10,24' : '10.24');
      await page.$eval('.oceano-lesson-exercise', (el) => el.scrollIntoView({ block: 'end' }));
      await page.evaluate(() => window.oceano.renderFrame());
      await page.screenshot({ path: `${process.env.OCEANO_SHOTS}/exercise-${width}x${height}-${lang}.png` });
      await page.close();
    }
  }, 600_000);
});
