import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { recordedPage, viewsReady } from './pages';
import { diffPngs } from './imageCompare';

/** What issue 11's new user tripped over, each checked the way they met it. */
const harness = useHarness();

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };

describe('notices', () => {
  it('in a 400-px figure, every one of seven notices wraps inside its box and can be scrolled to', async () => {
    const { page } = await recordedPage(harness, 600, 400);
    await page.goto(`${harness.baseUrl}fixtures/notices-400.html`, { waitUntil: 'load' });
    await viewsReady(page);
    const facts = await page.evaluate(() => {
      const view = document.querySelector('#bad') as ViewElement;
      const list = view.querySelector('.oceano-notices') as HTMLElement;
      const box = view.getBoundingClientRect();
      const items = Array.from(list.querySelectorAll<HTMLElement>('.oceano-notice'));
      const overflowing = items.filter((item) => item.scrollWidth > item.clientWidth + 1 || item.getBoundingClientRect().right > box.right + 0.5);
      // Scroll each notice into the list's view: it must then lie inside the figure.
      const reachable = items.filter((item) => {
        item.scrollIntoView({ block: 'nearest' });
        const r = item.getBoundingClientRect();
        return r.top >= box.top - 0.5 && r.bottom <= box.bottom + 0.5;
      });
      return { count: view.oceano!.notices().length, items: items.length, overflowing: overflowing.length, reachable: reachable.length, listBottom: list.getBoundingClientRect().bottom, boxBottom: box.bottom, width: box.width };
    });
    expect(facts.width).toBe(400);
    expect(facts.count).toBe(7);
    expect(facts.items).toBe(7);
    expect(facts.overflowing).toBe(0);
    expect(facts.reachable).toBe(7);
    expect(facts.listBottom).toBeLessThanOrEqual(facts.boxBottom);
    await page.close();
  });

  it('shows a refused share link wrapped beside the panel, selectable in one click', async () => {
    const { page } = await openOcean(harness, 't=4&seed=5', 800, 450);
    await page.evaluate(() => {
      Object.defineProperty(navigator, 'clipboard', { value: { writeText: () => Promise.reject(new DOMException('refused', 'NotAllowedError')) } });
    });
    const url = await page.evaluate(() => window.oceano.shareUrl());
    await page.evaluate(() => (Array.from(document.querySelectorAll<HTMLElement>('.lil-gui button')).find((b) => b.textContent?.includes('Share link')) as HTMLElement).click());
    await page.waitForFunction(() => window.oceano.notices().length > 0);
    const facts = await page.evaluate(() => {
      const notice = document.querySelector('.oceano-notice') as HTMLElement;
      const link = notice.querySelector('.oceano-notice-link') as HTMLElement;
      const panel = document.querySelector('.lil-gui') as HTMLElement;
      return {
        noticeRight: notice.getBoundingClientRect().right,
        panelLeft: panel.getBoundingClientRect().left,
        fits: notice.scrollWidth <= notice.clientWidth + 1,
        link: link.textContent,
        userSelect: getComputedStyle(link).userSelect,
        lines: Math.round(link.getBoundingClientRect().height / parseFloat(getComputedStyle(link).lineHeight)),
      };
    });
    expect(facts.link).toBe(url);
    expect(facts.fits).toBe(true);
    expect(facts.noticeRight).toBeLessThanOrEqual(facts.panelLeft);
    expect(facts.userSelect).toBe('all');
    expect(facts.lines).toBeGreaterThan(1);
    await page.close();
  });
});

describe('booting', () => {
  it('opened from disk, says in words to serve it over http(s), and oceano.ready rejects with that reason', async () => {
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
    await page.goto(pathToFileURL(join(import.meta.dirname, '..', '..', 'dist', 'index.html')).href, { waitUntil: 'load' });
    const facts = await page.evaluate(async () => {
      const api = (window as { oceano?: unknown }).oceano as { ready?: Promise<void> } | undefined;
      let rejection = 'did not reject';
      try {
        await api?.ready;
      } catch (error) {
        rejection = (error as Error).message;
      }
      const fatal = document.querySelector('.oceano-fatal') as HTMLElement | null;
      return { isElement: api instanceof Element, rejection, text: fatal?.innerText ?? '', visible: fatal !== null && fatal.getBoundingClientRect().height > 0 };
    });
    expect(facts.isElement).toBe(false);
    expect(facts.text).toMatch(/served over http\(s\)/);
    expect(facts.text).toContain('python3 -m http.server 8000');
    expect(facts.visible).toBe(true);
    expect(facts.rejection).toBe(facts.text);
    await page.close();
  });

  it('without WebGL2, oceano.ready rejects with the reason shown on the page', async () => {
    const page = await harness.browser.newPage();
    await page.evaluateOnNewDocument(() => {
      const original = HTMLCanvasElement.prototype.getContext;
      HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, kind: string, ...rest: unknown[]) {
        return kind === 'webgl2' ? null : (original as (k: string, ...r: unknown[]) => RenderingContext | null).call(this, kind, ...rest);
      } as typeof original;
    });
    await page.goto(harness.baseUrl, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined, { timeout: 10_000 });
    const rejection = await page.evaluate(() => window.oceano.ready.then(() => 'resolved', (error: Error) => error.message));
    expect(rejection).toMatch(/WebGL2/);
    expect(await page.$eval('.oceano-fatal', (el) => (el as HTMLElement).innerText)).toBe(rejection);
    await page.close();
  });
});

describe('Spanish page', () => {
  it('says a missing boat in Spanish only, and labels the Fresnel plot in Spanish', async () => {
    const { page } = await openOcean(harness, 'lang=es&t=2&fresnelPlot=1&boat=models/none.glb', 640, 360);
    const facts = await page.evaluate(() => ({ notices: window.oceano.notices(), plot: document.querySelector('.oceano-fresnel-plot')!.getAttribute('aria-label') }));
    expect(facts.notices).toEqual(['No se encontró el modelo del barco "models/none.glb" (HTTP 404). El océano sigue sin él.']);
    expect(facts.plot).toMatch(/^Gráfico de la reflectancia de Fresnel/);
    const plotPng = async () => Buffer.from(await (await page.$('.oceano-fresnel-plot'))!.screenshot({ type: 'png' }));
    const spanish = await plotPng();
    const english = await openOcean(harness, 'lang=en&t=2&fresnelPlot=1', 640, 360);
    const englishPlot = Buffer.from(await (await english.page.$('.oceano-fresnel-plot'))!.screenshot({ type: 'png' }));
    // Same curves, other words: the pictures differ only by their labels.
    expect(diffPngs(spanish, englishPlot, 0).differentPixels).toBeGreaterThan(200);
    await english.page.close();
    await page.close();
  });
});
