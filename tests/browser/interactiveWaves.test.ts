import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { fixtureBundle } from './fixtureBundle';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { BROWSER_ARGS, findBrowser } from './harness';
import type { InteractiveWavesApi } from './fixtures/interactiveWaves';

/**
 * The interactive waves in the library's Ocean: a dropped stone shows in the picture, and with
 * interactiveWaves on but the water calm the picture is the one without them (their code adds
 * nothing). The page is a bundle of tests/browser/fixtures/interactiveWaves.ts.
 */
let browser: Browser;
let page: Page;

beforeAll(async () => {
  const code = await fixtureBundle('interactiveWaves', true);
  browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  page = await browser.newPage();
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await page.setContent('<!doctype html><html><body></body></html>');
  await page.addScriptTag({ content: code, type: 'module' });
  await page.waitForFunction(() => 'interactiveWaves' in window, { timeout: 60_000 }).catch((e: unknown) => errors.push(String(e)));
  expect(errors).toEqual([]);
}, 300_000);

afterAll(async () => {
  await browser?.close();
});

const draw = (on: boolean, stone: boolean, seconds: number): ReturnType<InteractiveWavesApi['draw']> =>
  page.evaluate(
    (a, b, c) => (window as unknown as { interactiveWaves: InteractiveWavesApi }).interactiveWaves.draw(a, b, c),
    on,
    stone,
    seconds,
  );

function differing(a: number[], b: number[], threshold: number): number {
  let count = 0;
  for (let i = 0; i < a.length; i += 4) {
    const d = Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2]));
    if (d > threshold) count++;
  }
  return count;
}

describe('interactive waves in the Ocean', () => {
  // Planted fault: the stone left out changes nothing.
  it("draws a dropped stone's rings, and a calm field draws as no field", async () => {
    const off = await draw(false, false, 0.25);
    const calm = await draw(true, false, 0.25);
    const stone = await draw(true, true, 0.25);
    expect(off.fragmentHasField).toBe(false);
    expect(calm.fragmentHasField).toBe(true);
    const pixels = off.pixels.length / 4;
    const calmChanged = differing(calm.pixels, off.pixels, 1);
    const stoneChanged = differing(stone.pixels, off.pixels, 1);
    const mean = (p: number[]) => p.reduce((s, v) => s + v, 0) / p.length;
    console.log(
      `Field's largest height with the stone: ${stone.largestHeight.toFixed(3)} m; mean pixel value ${mean(stone.pixels).toFixed(1)}`,
    );
    console.log(
      `Pixels off by more than 1 level from the view without the field: calm field ${calmChanged}, stone ${stoneChanged} of ${pixels}`,
    );
    expect(calmChanged).toBe(0);
    expect(stoneChanged).toBeGreaterThan(0.01 * pixels);
  }, 600_000);

  // The picture differs from the same field with the tint and foam cut out of ocean.frag (planted fault: cut
  // from both, nothing differs).
  it("tints steep water paler and greener, and foams it past 60 % of Stokes's limit", async () => {
    const steep = (fault: boolean) =>
      page.evaluate((f) => (window as unknown as { interactiveWaves: InteractiveWavesApi }).interactiveWaves.steep(f), fault);
    /** Pixels that differ, and how much greener they came out on average (levels of green). */
    const tinted = (a: number[], b: number[]) => {
      let count = 0;
      let green = 0;
      for (let i = 0; i < a.length; i += 4) {
        if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) <= 2) continue;
        count++;
        green += a[i + 1] - b[i + 1];
      }
      return { count, green: count ? green / count : 0 };
    };
    const shown = await steep(false);
    const cut = await steep(true);
    const cutAgain = await steep(true);
    const pixels = shown.pixels.length / 4;
    const tint = tinted(shown.pixels, cut.pixels);
    const control = tinted(cutAgain.pixels, cut.pixels);
    console.log(
      `Steepest slope of the field ${shown.steepest.toFixed(2)} (tint from 0.03, foam from 0.35, Stokes's limit 0.58); pixels changed by the tint and foam ${tint.count} of ${pixels}, ${tint.green.toFixed(1)} levels greener on average; with both cut: ${control.count}`,
    );
    expect(shown.steepest).toBeGreaterThan(0.35);
    expect(tint.count).toBeGreaterThan(0.01 * pixels);
    expect(tint.green).toBeGreaterThan(5);
    expect(control.count).toBe(0);
  }, 600_000);

  // Planted fault: a stone a step later differs.
  it('gives the same field whether the clock plays, steps or jumps, and replays the stones after a jump back', async () => {
    const played = (times: number[], stones: { time: number; x: number; z: number }[]) =>
      page.evaluate(
        (t, s) => (window as unknown as { interactiveWaves: InteractiveWavesApi }).interactiveWaves.played(t, s),
        times,
        stones,
      );
    const stones = [{ time: 0.1, x: 1, z: -2 }];
    // Frames at 60 Hz to 0.5 s; frames of uneven length; a jump from the stone to 0.5 s; and a
    // run past 0.5 s then back to it (the field restarts calm and replays the stone).
    const frames = Array.from({ length: 31 }, (_, k) => k / 60);
    const uneven = [0, 0.05, 0.1, 0.13, 0.29, 0.31, 0.42, 0.5];
    const jump = [0, 0.1, 0.5];
    const back = [0, 0.1, 0.3, 0.7, 0.5];
    const reference = await played(frames, stones);
    expect(Math.max(...reference.map(Math.abs))).toBeGreaterThan(0.01);
    for (const times of [uneven, jump, back]) expect(await played(times, stones)).toEqual(reference);
    const later = await played([0, 0.1, 0.13, 0.5], [{ time: 0.13, x: 1, z: -2 }]);
    expect(later).not.toEqual(reference);
  }, 600_000);

  // Planted fault: a texel off does not.
  it('lets sampleSurface see the field through its read-back: at texel centres it gives the texel', async () => {
    // Texel centres of the grid centred on the origin lie at odd multiples of 0.25 m.
    const points: [number, number][] = [
      [0.25, 0.25],
      [2.75, -1.25],
      [-4.25, 3.75],
    ];
    const { sampled, texels } = await page.evaluate(
      (p) => (window as unknown as { interactiveWaves: InteractiveWavesApi }).interactiveWaves.sampled(p),
      points,
    );
    console.log(
      `sampleSurface ${sampled.map((h) => h.toFixed(5)).join(', ')} m; field texels ${texels.map((h) => h.toFixed(5)).join(', ')} m`,
    );
    expect(Math.max(...texels.map(Math.abs))).toBeGreaterThan(0.01);
    for (let k = 0; k < points.length; k++) expect(Math.abs(sampled[k] - texels[k])).toBeLessThan(1e-6);
    expect(Math.abs(sampled[0] - texels[1])).toBeGreaterThan(1e-3);
  }, 600_000);
});
