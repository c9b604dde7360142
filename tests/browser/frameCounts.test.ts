import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { openOcean } from './harness';
import { useHarness } from './useHarness';

const harness = useHarness();

async function counts(page: Page, options: { seconds?: number; plantedPass?: boolean } = {}) {
  await page.evaluate(() => window.oceano.pause());
  // Warm-up frames: programs compiled, the boat's first placement, a replay of the stones done.
  for (let i = 0; i < 3; i++) await page.evaluate((o) => window.oceano.debug.frameCounts(o), options);
  return page.evaluate((o) => window.oceano.debug.frameCounts(o), options);
}

describe('measure', () => {
  for (const query of ['t=10&preset=stone']) {
    it(query, async () => {
      const { page } = await openOcean(harness, query, 1280, 720);
      console.log(query, JSON.stringify(await counts(page)), JSON.stringify(await counts(page, { seconds: 0 })));
      await page.close();
    }, 300_000);
  }
});
