import { describe, expect, it } from 'vitest';
import puppeteer from 'puppeteer';
import { BROWSER_ARGS, findBrowser } from './harness';
import { useHarness } from './useHarness';
import { serveUnderSubPath } from './staticServer';

describe('deployment', () => {
  const harness = useHarness();

  it('works from a static copy of dist/ under any sub-path (relative base)', async () => {
    const { server, url } = await serveUnderSubPath();
    const page = await harness.browser.newPage();
    const failed: string[] = [];
    page.on('response', (response) => {
      if (response.status() >= 400) failed.push(`${response.status()} ${response.url()}`);
    });
    try {
      await page.setViewport({ width: 320, height: 180 });
      await page.goto(`${url}?t=3`, { waitUntil: 'load' });
      await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
      await page.evaluate(() => window.oceano.ready);
      expect(failed).toEqual([]);
      expect(await page.evaluate(() => window.oceano.notices())).toEqual([]);
    } finally {
      await page.close();
      server.close();
    }
  });

  it('tells a browser without WebGL2 so, in words, instead of a blank page', async () => {
    const browser = await puppeteer.launch({
      executablePath: await findBrowser(),
      args: [...BROWSER_ARGS, '--disable-webgl', '--disable-webgl2'],
    });
    try {
      const page = await browser.newPage();
      const errors: string[] = [];
      page.on('pageerror', (error) => errors.push(String(error)));
      await page.goto(harness.baseUrl, { waitUntil: 'load' });
      await page.waitForSelector('.oceano-fatal');
      const text = await page.$eval('.oceano-fatal', (el) => (el as HTMLElement).innerText);
      expect(text).toMatch(/WebGL2/);
      expect(errors).toEqual([]);
    } finally {
      await browser.close();
    }
  });
});
