import { describe, expect, it } from 'vitest';
import { canvasPng, openOcean } from './harness';
import { diffPngs } from './imageCompare';
import { useHarness } from './useHarness';

/** A share link reopens the boat where it was. */
const harness = useHarness();

describe('share link and the boat', () => {
  const settle = (page: import('puppeteer').Page, ms: number) => page.evaluate((wait) => new Promise((r) => setTimeout(r, wait)), ms);

  for (const steered of [false, true]) {
    it(`reopens a ${steered ? 'steered' : 'free-running'} boat where it was, pixel for pixel`, async () => {
      const { page } = await openOcean(harness, 'seed=3', 640, 360);
      if (steered) {
        // Under SwiftShader a frame takes 0.1 s of simulated time at most (the clock clamps it),
        // so a second of keys moves the boat only metres: start at speed.
        await page.evaluate(() => window.oceano.setParams({ boatSpeed: 6 }));
        await page.keyboard.down('KeyW');
        await settle(page, 1500);
        await page.keyboard.up('KeyW');
        await page.keyboard.down('KeyD');
        await settle(page, 800);
        await page.keyboard.up('KeyD');
      } else {
        await settle(page, 2000);
      }
      await page.evaluate(() => window.oceano.pause());
      const original = await canvasPng(page);
      const boat = await page.evaluate(() => window.oceano.boat());
      const url = await page.evaluate(() => window.oceano.shareUrl());
      expect(url).toContain('boatState=');
      if (steered) expect(Math.hypot(boat.position[0] - 7, boat.position[2] + 5)).toBeGreaterThan(0.01);
      const shared = await harness.browser.newPage();
      await shared.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
      await shared.goto(url, { waitUntil: 'load' });
      await shared.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
      await shared.evaluate(() => window.oceano.ready);
      const again = await shared.evaluate(() => window.oceano.boat());
      expect(again.position).toEqual(boat.position);
      expect([again.heading, again.pitch, again.roll]).toEqual([boat.heading, boat.pitch, boat.roll]);
      expect(diffPngs(original, await canvasPng(shared), 0).differentPixels).toBe(0);
      await shared.close();
      await page.close();
    });
  }
});
