import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { useHarness } from './useHarness';
import { diffPngs } from './imageCompare';
import { elementCanvasPng, recordedPage } from './pages';
import { heapFigures, heapLessCode, type HeapFigures } from './heapFigures';
import { visibleFiguresReady } from '../support/visibleFigures';

const jsValues = (heap: HeapFigures) => heap.snapshot.values;

const harness = useHarness();

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };

interface ContextCount {
  created: number;
  live: number;
  maxLive: number;
  errors: { type: string; message: string }[];
}

/**
 * Counts the page's WebGL contexts as they are made (the most alive at once) and the
 * figures' error events. Installed before the page's own scripts run.
 */
async function countContexts(page: Page): Promise<void> {
  await page.evaluateOnNewDocument(() => {
    const refs: WeakRef<WebGLRenderingContext | WebGL2RenderingContext>[] = [];
    const seen = new WeakSet<object>();
    const count = {
      created: 0,
      maxLive: 0,
      errors: [] as { type: string; message: string }[],
      live: () => refs.filter((r) => r.deref()?.isContextLost() === false).length,
    };
    (window as unknown as { __contexts: typeof count }).__contexts = count;
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, type: string, ...rest: unknown[]) {
      const context = (getContext as (this: HTMLCanvasElement, ...a: unknown[]) => RenderingContext | null).call(this, type, ...rest);
      if (context && (type === 'webgl2' || type === 'webgl') && !seen.has(context)) {
        seen.add(context);
        refs.push(new WeakRef(context as WebGL2RenderingContext));
        count.created++;
        count.maxLive = Math.max(count.maxLive, count.live());
      }
      return context;
    } as typeof getContext;
    document.addEventListener(
      'error',
      (event) => {
        const detail = (event as unknown as CustomEvent<{ type: string; message: string }>).detail;
        if (detail?.type) count.errors.push(detail);
      },
      true,
    );
  });
}

const contextCount = (page: Page): Promise<ContextCount> =>
  page.evaluate(() => {
    const c = (
      window as unknown as { __contexts: { created: number; maxLive: number; errors: { type: string; message: string }[]; live(): number } }
    ).__contexts;
    return { created: c.created, live: c.live(), maxLive: c.maxLive, errors: c.errors };
  });

/**
 * Waits until the figures that have started (those on screen and those within the half screen
 * where figures start ahead) are all drawn, and no other has started for a second: the heap is
 * measured with the same figures alive whatever the machine's speed.
 */
async function startedFiguresSettled(page: Page): Promise<void> {
  await page.evaluate(async () => {
    const started = () => (Array.from(document.querySelectorAll('oceano-view')) as ViewElement[]).filter((view) => view.oceano !== null);
    for (let before = -1; ;) {
      const views = started();
      await Promise.all(views.map((view) => view.oceano!.ready));
      await new Promise((resolve) => setTimeout(resolve, 1000));
      if (started().length === views.length && views.length === before) return;
      before = views.length;
    }
  });
}

/**
 * How far the page's JavaScript values (a heap snapshot's objects, arrays, strings, closures,
 * numbers) may be above the first visit once back at the top. The engine's own structures are
 * left out: its compiled code and the hidden classes beside it grow once per page, not per
 * figure, as the figures lower down run code the first screen never did (other wave models,
 * the underwater passes, the comparison), which V8 compiles, optimizes and keeps
 * (docs/course-pages.md, "The heap").
 */
const HEAP_GROWTH = 1.1;

async function heap(page: Page): Promise<HeapFigures> {
  const session = await page.createCDPSession();
  const figures = await heapFigures(session);
  await session.detach();
  return figures;
}

const mb = (bytes: number) => (bytes / 1e6).toFixed(2);
const heapText = (figures: HeapFigures) =>
  `${mb(figures.used)} MB (${mb(figures.snapshot.code)} of it compiled code, ${mb(heapLessCode(figures))} without; JavaScript values ${mb(jsValues(figures))})`;

/** Scrolls the page from top to bottom one screen at a time, waiting at each stop for the figures on screen. */
async function scrollThrough(page: Page, positions: number[]): Promise<void> {
  for (const y of positions) {
    await page.evaluate((top) => window.scrollTo(0, top), y);
    await visibleFiguresReady(page);
  }
}

describe('<oceano-view> on a page of thirty figures', () => {
  // It gives the browser no context to take.
  it('holds only the figures near the screen live and brings each back as it was', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 800, 600);
    const warnings: string[] = [];
    page.on('console', (m) => warnings.push(m.text()));
    await countContexts(page);
    await page.goto(`${harness.baseUrl}fixtures/thirty-views.html`, { waitUntil: 'load' });
    await visibleFiguresReady(page);
    const started = performance.now();

    // The wake figure near the top, as first seen: its share link and its picture.
    const wakeFigure = '#f1';
    const before = {
      link: await page.evaluate((s) => (document.querySelector(s) as ViewElement).oceano!.shareUrl(), wakeFigure),
      png: await elementCanvasPng(page, wakeFigure),
    };
    await startedFiguresSettled(page);
    const heapFirst = await heap(page);
    const liveFirst = (await contextCount(page)).live;
    const waiting = await page.evaluate(
      () =>
        (Array.from(document.querySelectorAll('oceano-view')) as ViewElement[]).filter(
          (v) => v.oceano === null && !v.querySelector('canvas'),
        ).length,
    );
    // Lazy: the figures far below have no canvas at all yet.
    expect(waiting).toBeGreaterThan(20);

    const bottom = await page.evaluate(() => document.documentElement.scrollHeight - innerHeight);
    const down: number[] = [];
    for (let y = 600; y < bottom; y += 600) down.push(y);
    down.push(bottom);
    await scrollThrough(page, down);
    const atBottom = await contextCount(page);
    // The wake figure is far away now: no context, its last frame kept as a still.
    const away = await page.evaluate((s) => {
      const view = document.querySelector(s) as ViewElement;
      return {
        api: view.oceano,
        webgl: view.querySelector('canvas.oceano-canvas') !== null,
        still: view.querySelector('canvas.oceano-still') !== null,
      };
    }, wakeFigure);
    expect(away).toEqual({ api: null, webgl: false, still: true });

    // Back up three screens at a time: the figures passed over come back too, more slowly.
    await scrollThrough(
      page,
      [...down]
        .reverse()
        .filter((_, i) => i % 3 === 2)
        .concat([0]),
    );
    const after = await contextCount(page);
    const back = {
      link: await page.evaluate((s) => (document.querySelector(s) as ViewElement).oceano!.shareUrl(), wakeFigure),
      png: await elementCanvasPng(page, wakeFigure),
    };
    await startedFiguresSettled(page);
    const heapBack = await heap(page);
    console.log(
      `thirty figures: ${after.created} contexts made, at most ${after.maxLive} alive at once (${atBottom.live} at the bottom, ${after.live} back at the top); ` +
        `heap ${heapText(heapFirst)} first, ${heapText(heapBack)} back at the top; scroll took ${((performance.now() - started) / 1000).toFixed(1)} s`,
    );

    expect(after.errors).toEqual([]);
    expect(warnings.filter((w) => w.includes('Too many active WebGL contexts'))).toEqual([]);
    expect(after.maxLive).toBeLessThanOrEqual(12);
    // Every figure started at least once, and those scrolled away came back with fresh contexts.
    expect(after.created).toBeGreaterThan(30);
    // Time, camera, parameters, the boat's motion and the wake's track are as they were, and so is the picture.
    expect(back.link).toBe(before.link);
    expect(diffPngs(before.png, back.png).share).toBeLessThan(0.001);
    // Back at the top, the same figures hold contexts as on the first visit, and the heap is as
    // it was but for each released figure's saved view (its still is a canvas, outside the heap).
    expect(after.live).toBeLessThanOrEqual(liveFirst);
    expect(jsValues(heapBack)).toBeLessThan(jsValues(heapFirst) * HEAP_GROWTH);
    expect(consoleErrors).toEqual([]);
    await page.close();
  }, 500_000);

  // Contexts are taken from the figures; the heap is measured back at the top.
  it('control: with releasing off, the browser takes contexts away and the heap grows past the bound', async () => {
    const { page } = await recordedPage(harness, 800, 600);
    const warnings: string[] = [];
    page.on('console', (m) => warnings.push(m.text()));
    await countContexts(page);
    await page.goto(`${harness.baseUrl}fixtures/thirty-views.html`, { waitUntil: 'load' });
    await page.waitForFunction(() => customElements.get('oceano-view') !== undefined);
    await page.evaluate(() => ((customElements.get('oceano-view') as unknown as { releaseContexts: boolean }).releaseContexts = false));
    await visibleFiguresReady(page);
    const heapFirst = await heap(page);
    // Down the page until the browser, which keeps sixteen contexts, takes one away.
    const bottom = await page.evaluate(() => document.documentElement.scrollHeight - innerHeight);
    for (let y = 600; (await contextCount(page)).errors.length === 0 && y <= bottom; y += 600) await scrollThrough(page, [y]);
    const count = await contextCount(page);
    expect(count.errors[0].type).toBe('contextlost');
    expect(count.maxLive).toBeGreaterThan(12);
    expect(warnings.some((w) => w.includes('Too many active WebGL contexts'))).toBe(true);
    // The figure that lost its context says so where it stood.
    expect(await page.evaluate(() => document.querySelectorAll('oceano-view .oceano-notice').length)).toBeGreaterThan(0);
    // Every figure passed over still holds its ocean: back at the top, the heap is far past the bound.
    await scrollThrough(page, [0]);
    const heapBack = await heap(page);
    console.log(`thirty figures, releasing off: heap ${heapText(heapFirst)} first, ${heapText(heapBack)} back at the top`);
    expect(jsValues(heapBack)).toBeGreaterThan(jsValues(heapFirst) * HEAP_GROWTH);
    await page.close();
  });
});
