import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { useHarness } from './useHarness';
import { recordedPage } from './pages';

const harness = useHarness();

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };

const camera = (page: Page) => page.evaluate(() => (document.getElementById('touched') as ViewElement).oceano!.getCamera());
const blur = (page: Page) => page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());

/** One finger (or two, side by side) put down at the figure's centre and drawn by (dx, dy) in small steps. */
async function drag(page: Page, dx: number, dy: number, fingers: 1 | 2): Promise<void> {
  const box = (await (await page.$('#touched'))!.boundingBox())!;
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  const starts =
    fingers === 1
      ? [[x, y]]
      : [
          [x - 30, y],
          [x + 30, y],
        ];
  const touches = [];
  for (const [sx, sy] of starts) touches.push(await page.touchscreen.touchStart(sx, sy));
  for (let step = 1; step <= 8; step++) {
    for (let i = 0; i < touches.length; i++) await touches[i].move(starts[i][0] + (dx * step) / 8, starts[i][1] + (dy * step) / 8);
  }
  // Held still before lifting, so the browser starts no fling: a tap during one only stops it.
  await new Promise((r) => setTimeout(r, 200));
  for (const touch of touches) await touch.end();
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

describe('<oceano-view> on a touch screen', () => {
  it('lets one finger scroll the page past the figure, and orbits only after a tap or with two fingers', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 400, 600);
    await page.setViewport({ width: 400, height: 600, deviceScaleFactor: 1, hasTouch: true, isMobile: true });
    await page.goto(`${harness.baseUrl}fixtures/touch.html`, { waitUntil: 'load' });
    await page.waitForFunction(() => (document.getElementById('touched') as ViewElement | null)?.oceano);
    await page.evaluate(() => (document.getElementById('touched') as ViewElement).oceano!.ready);
    const start = await camera(page);

    // A vertical swipe over the figure scrolls the page and leaves the view alone.
    await drag(page, 0, -150, 1);
    expect(await page.evaluate(() => scrollY)).toBeGreaterThan(50);
    expect(await camera(page)).toEqual(start);
    await page.evaluate(() => scrollTo(0, 0));

    // Neither does a sideways swipe move it, while the figure has not been tapped.
    await drag(page, 120, 0, 1);
    expect(await camera(page)).toEqual(start);

    // Control, the same swipe after a tap: the figure has the focus, and it orbits.
    const box = (await (await page.$('#touched'))!.boundingBox())!;
    await page.touchscreen.tap(box.x + box.width / 2, box.y + box.height / 2);
    // The focus follows the tap's compatibility mouse events, a moment after the touch ends.
    await page.waitForFunction(() => document.activeElement?.classList.contains('oceano-canvas') ?? false, { timeout: 5000 });
    await drag(page, 120, 0, 1);
    const tapped = await camera(page);
    expect(tapped.position).not.toEqual(start.position);

    // Focus elsewhere: one finger passes over it again, and two fingers orbit.
    await blur(page);
    await drag(page, 120, 0, 1);
    expect(await camera(page)).toEqual(tapped);
    await drag(page, 120, 0, 2);
    expect((await camera(page)).position).not.toEqual(tapped.position);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
