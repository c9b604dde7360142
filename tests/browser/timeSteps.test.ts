import type { Page } from 'puppeteer';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import { screenshotCanvas } from './harness';
import { useHarness } from './useHarness';
import { VIRTUAL_FRAMES, type Pumped } from './virtualFrames';

const harness = useHarness();

describe('slow motion and Step', () => {
  // Control: one step more differs.
  it('stepping N frames at timeScale 0.5 draws exactly the picture playing N frames draws', async () => {
    const N = 12;
    const open = async () => {
      const page = await harness.browser.newPage();
      await page.evaluateOnNewDocument(VIRTUAL_FRAMES);
      await page.setViewport({ width: 480, height: 270, deviceScaleFactor: 1 });
      page.setDefaultTimeout(120_000);
      await page.goto(`${harness.baseUrl}?t=2&timeScale=0.5`, { waitUntil: 'load' });
      await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
      await page.evaluate(() => window.oceano.ready);
      await page.evaluate(() => (window as unknown as Pumped).manualFrames());
      await page.evaluate(() => (window as unknown as Pumped).pumpFrames(2));
      return page;
    };
    const time = (page: Page) => page.evaluate(() => Number(new URL(window.oceano.shareUrl()).searchParams.get('t')));
    // Paused: frames running by themselves now draw nothing new, and the screenshot gets its own.
    const picture = async (page: Page) => {
      await page.evaluate(() => (window as unknown as Pumped).autoFrames());
      const png = PNG.sync.read(await screenshotCanvas(page)).data;
      await page.evaluate(() => (window as unknown as Pumped).manualFrames());
      return png;
    };
    // One page at a time: a tab in the background is not drawn, so it is pictured and closed first.
    const played = await open();
    // The loop's first frame measures no time (nothing before it): N + 1 frames advance N.
    await played.evaluate((n) => {
      window.oceano.play();
      (window as unknown as Pumped).pumpFrames(n + 1);
      window.oceano.pause();
    }, N);
    expect(await time(played)).toBeCloseTo(2 + (N * 0.5) / 60, 9);
    const a = await picture(played);
    const playedBoat = await played.evaluate(() => window.oceano.boat());
    await played.close();

    const stepped = await open();
    await stepped.evaluate((n) => {
      for (let i = 0; i < n; i++) {
        window.oceano.step();
        (window as unknown as Pumped).pumpFrames(1);
      }
    }, N);
    expect(await time(stepped)).toBeCloseTo(2 + (N * 0.5) / 60, 9);
    const b = await picture(stepped);
    expect(Buffer.compare(a, b)).toBe(0);
    expect(await stepped.evaluate(() => window.oceano.boat())).toEqual(playedBoat);
    await stepped.evaluate(() => {
      window.oceano.step();
      (window as unknown as Pumped).pumpFrames(1);
    });
    const c = await picture(stepped);
    let differing = 0;
    for (let i = 0; i < a.length; i += 4) if (a[i] !== c[i] || a[i + 1] !== c[i + 1] || a[i + 2] !== c[i + 2]) differing++;
    expect(differing).toBeGreaterThan(100);
    await stepped.close();
  });
});
