import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { recordedPage, viewsReady } from './pages';
import { diffPngs } from './imageCompare';
import { useHarness } from './useHarness';

/** Notices a user meets: readable in a small figure, in the page's language, a refused link selectable. */
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
      const overflowing = items.filter(
        (item) => item.scrollWidth > item.clientWidth + 1 || item.getBoundingClientRect().right > box.right + 0.5,
      );
      // Scroll each notice into the list's view: it must then lie inside the figure.
      const reachable = items.filter((item) => {
        item.scrollIntoView({ block: 'nearest' });
        const r = item.getBoundingClientRect();
        return r.top >= box.top - 0.5 && r.bottom <= box.bottom + 0.5;
      });
      return {
        count: view.oceano!.notices().length,
        items: items.length,
        overflowing: overflowing.length,
        reachable: reachable.length,
        listBottom: list.getBoundingClientRect().bottom,
        boxBottom: box.bottom,
        width: box.width,
      };
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
      Object.defineProperty(navigator, 'clipboard', {
        value: { writeText: () => Promise.reject(new DOMException('refused', 'NotAllowedError')) },
      });
    });
    const url = await page.evaluate(() => window.oceano.shareUrl());
    await page.evaluate(() =>
      (
        Array.from(document.querySelectorAll<HTMLElement>('.lil-gui button')).find((b) =>
          b.textContent?.includes('Share link'),
        ) as HTMLElement
      ).click(),
    );
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

describe('Spanish page', () => {
  it('says a missing boat in Spanish only, and labels the Fresnel plot in Spanish', async () => {
    const { page } = await openOcean(harness, 'lang=es&t=2&fresnelPlot=1&boat=models/none.glb', 640, 360);
    const facts = await page.evaluate(() => ({
      notices: window.oceano.notices(),
      plot: document.querySelector('.oceano-fresnel-plot')!.getAttribute('aria-label'),
    }));
    // The preview server answers a missing file with its index page (boatWebPage) or a 404 (boatNotFound): either, all in Spanish.
    expect(facts.notices).toHaveLength(1);
    expect(facts.notices[0]).toMatch(
      /^(No se encontró el modelo del barco "models\/none\.glb" \(HTTP 404\)|Falta el modelo del barco "models\/none\.glb": el servidor envió una página web en su lugar)\. El océano sigue sin él\.$/,
    );
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
