import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { useHarness } from './useHarness';
import { recordedPage } from './pages';
import { ensurePosters } from './distPosters';

const harness = useHarness();

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };

/** Records every figure's error event from before the page's scripts run. */
async function recordFigureErrors(page: Page): Promise<void> {
  await page.evaluateOnNewDocument(() => {
    const errors: unknown[] = [];
    (window as unknown as { __figureErrors: unknown[] }).__figureErrors = errors;
    document.addEventListener('error', (event) => {
      if ((event.target as Element).localName === 'oceano-view') errors.push((event as unknown as CustomEvent).detail);
    }, true);
  });
}

/** Waits until every figure on screen has started and drawn. */
async function visibleFiguresReady(page: Page): Promise<number> {
  const onScreen = `Array.from(document.querySelectorAll('oceano-view')).filter((view) => {
    const box = view.getBoundingClientRect();
    return box.bottom > 0 && box.top < innerHeight;
  })`;
  await page.waitForFunction(`${onScreen}.every((view) => view.oceano !== null)`);
  return page.evaluate(`Promise.all(${onScreen}.map((view) => view.oceano.ready)).then((all) => all.length)`) as Promise<number>;
}

describe('the course page (dist/course/)', () => {
  // Its figures point at the build's posters.
  beforeAll(() => ensurePosters(harness), 600_000);

  it('is the seed report made live: every figure starts as it is scrolled to, with no lost context, notice or page error', async () => {
    const { page, consoleErrors, violations } = await recordedPage(harness, 800, 700);
    // Figures open paused under reduced motion: the page is scrolled, not watched.
    await page.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'reduce' }]);
    await recordFigureErrors(page);
    await page.goto(`${harness.baseUrl}course/index.html?lang=es`, { waitUntil: 'load' });
    const outline = await page.evaluate(() => ({
      figures: document.querySelectorAll('oceano-view').length,
      sections: Array.from(document.querySelectorAll('main section h2 .es'), (h) => h.textContent),
      lang: document.documentElement.lang,
      figureLanguages: new Set(Array.from(document.querySelectorAll('oceano-view'), (v) => v.getAttribute('lang'))).size,
      englishShown: Array.from(document.querySelectorAll('.en')).some((e) => (e as HTMLElement).offsetParent !== null),
    }));
    expect(outline.figures).toBeGreaterThanOrEqual(24);
    expect(outline.sections.slice(0, 10)).toEqual(['Superficie del agua', 'Movimiento', 'Ruido de Perlin', 'Normales', 'Environment map', 'Óptica: Snell y Fresnel', 'CPU shader: mover el bote', 'Bajo el agua', 'Optimización: niveles de detalle', 'Frustum culling']);
    expect(outline.lang).toBe('es');
    expect(outline.figureLanguages).toBe(1);
    expect(outline.englishShown).toBe(false);

    // Each figure's caption quotes the lines of code behind it, as they are in the source now.
    const quotes = await page.evaluate(() =>
      Array.from(document.querySelectorAll('figure'), (figure) => ({
        summary: figure.querySelector('.code-quote summary')?.textContent ?? null,
        code: figure.querySelector('.code-quote code')?.textContent ?? null,
        link: figure.querySelector<HTMLAnchorElement>('a.open-in-app')!.search,
      })),
    );
    const quoted = quotes.filter((q) => q.code !== null);
    expect(quoted.length).toBeGreaterThanOrEqual(20);
    for (const q of quoted) {
      const [, file] = /^El código: (.+), \d+–\d+$/.exec(q.summary!)!;
      expect(readFileSync(join(import.meta.dirname, '..', '..', file), 'utf8')).toContain(q.code);
    }
    expect(quotes.every((q) => /^\?(lesson|preset)=[a-z-]+&lang=es$/.test(q.link))).toBe(true);

    // The figures far below, not started, show their posters: the build's picture of their preset.
    await page.waitForFunction(() => Array.from(document.querySelectorAll<HTMLImageElement>('img.oceano-poster')).every((img) => img.complete));
    const posters = await page.evaluate(() => ({
      withPoster: document.querySelectorAll('oceano-view[poster]').length,
      shown: Array.from(document.querySelectorAll<HTMLImageElement>('img.oceano-poster')).filter((img) => img.naturalWidth === 320).length,
      waiting: (Array.from(document.querySelectorAll('oceano-view[poster]')) as ViewElement[]).filter((view) => view.oceano === null).length,
    }));
    expect(posters.withPoster).toBeGreaterThanOrEqual(23);
    expect(posters.waiting).toBeGreaterThan(10);
    expect(posters.shown).toBeGreaterThanOrEqual(posters.waiting);

    const started = new Set<number>();
    const bottom = await page.evaluate(() => document.documentElement.scrollHeight - innerHeight);
    for (let y = 0; ; y = Math.min(y + 700, bottom)) {
      await page.evaluate((top) => window.scrollTo(0, top), y);
      await visibleFiguresReady(page);
      const live = await page.evaluate(() =>
        (Array.from(document.querySelectorAll('oceano-view')) as ViewElement[]).flatMap((view, i) => (view.oceano ? [i] : [])),
      );
      for (const i of live) started.add(i);
      expect(await page.evaluate(() => document.querySelectorAll('oceano-view .oceano-notice').length)).toBe(0);
      if (y === bottom) break;
    }
    expect(started.size).toBe(outline.figures);
    expect(await page.evaluate(() => (window as unknown as { __figureErrors: unknown[] }).__figureErrors)).toEqual([]);
    expect(consoleErrors).toEqual([]);
    expect(violations).toEqual([]);
    await page.close();
  }, 400_000);

  it('is linked from the app, after its lessons, in the reader\'s language', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 1366, 768);
    await page.goto(`${harness.baseUrl}index.html?lang=es`, { waitUntil: 'load' });
    const link = await page.waitForSelector('a.oceano-lessons-course');
    const { href, text, last } = await link!.evaluate((a) => ({ href: (a as HTMLAnchorElement).href, text: a.textContent, last: a.closest('li') === a.closest('ol')!.lastElementChild }));
    expect(last).toBe(true);
    expect(text).toMatch(/^La página del curso/);
    expect(href).toBe(`${harness.baseUrl}course/index.html?lang=es`);
    await Promise.all([page.waitForNavigation(), link!.click()]);
    expect(await page.evaluate(() => document.querySelectorAll('oceano-view').length)).toBeGreaterThanOrEqual(24);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('speaks English when asked, figures included', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 800, 700);
    await page.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'reduce' }]);
    await page.goto(`${harness.baseUrl}course/index.html?lang=en`, { waitUntil: 'load' });
    // The first figure may lie just below the first screen, within starting distance.
    await page.waitForFunction(() => (document.querySelector('oceano-view') as ViewElement).oceano !== null);
    await page.evaluate(() => (document.querySelector('oceano-view') as ViewElement).oceano!.ready);
    const facts = await page.evaluate(() => ({
      title: (document.querySelector('h1 .en') as HTMLElement).offsetParent !== null && (document.querySelector('h1 .es') as HTMLElement).offsetParent === null,
      label: document.querySelector('oceano-view canvas.oceano-canvas')!.getAttribute('aria-label'),
      link: (document.querySelector('a.open-in-app') as HTMLAnchorElement).search,
    }));
    expect(facts).toEqual({ title: true, label: 'The flat wireframe grid, before any displacement', link: '?lesson=flat-plane&lang=en' });
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
