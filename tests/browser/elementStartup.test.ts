import { afterAll, describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { useHarness } from './useHarness';
import { recordedPage, type RecordedPage } from './pages';

const harness = useHarness();

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };
interface HeardEvent {
  id: string;
  type: string;
  detail: { type?: string; message?: string; totalProgress?: number } | null;
}

/**
 * startup.html, opened once: its figures start in seconds of SwiftShader work each. Every
 * event a figure fires is recorded from before the page's own script runs.
 */
let opened: Promise<RecordedPage> | undefined;
const openStartup = async (): Promise<RecordedPage> => {
  const recorded = await (opened ??= recordedPage(harness, 800, 600).then(async (r) => {
    await r.page.evaluateOnNewDocument(() => {
      const heard: HeardEvent[] = [];
      (window as unknown as { __heard: HeardEvent[] }).__heard = heard;
      for (const type of ['progress', 'load', 'ready', 'error']) {
        document.addEventListener(
          type,
          (event) => {
            const target = event.target as Element;
            if (target.localName === 'oceano-view') heard.push({ id: target.id, type, detail: (event as CustomEvent).detail ?? null });
          },
          true,
        );
      }
    });
    await r.page.goto(`${harness.baseUrl}fixtures/startup.html`, { waitUntil: 'load' });
    return r;
  }));
  await recorded.page.bringToFront();
  return recorded;
};
afterAll(async () => {
  if (opened) await (await opened).page.close();
});

const heard = (page: Page, id: string, type?: string): Promise<HeardEvent[]> =>
  page.evaluate(
    (i, t) => (window as unknown as { __heard: HeardEvent[] }).__heard.filter((e) => e.id === i && (t === undefined || e.type === t)),
    id,
    type,
  );

const figureState = (page: Page, id: string) =>
  page.evaluate((i) => {
    const view = document.getElementById(i) as ViewElement;
    const canvas = view.querySelector('canvas.oceano-canvas');
    const poster = view.querySelector('img.oceano-poster') as HTMLImageElement | null;
    return {
      api: view.oceano !== null,
      canvas: canvas !== null,
      label: canvas?.getAttribute('aria-label') ?? null,
      poster: poster ? { alt: poster.alt, src: new URL(poster.src).pathname.split('/').pop() } : null,
      reveal: view.querySelector('button.oceano-reveal') !== null,
      touchAction: canvas ? getComputedStyle(canvas).touchAction : null,
    };
  }, id);

const readyOf = (page: Page, id: string) =>
  page
    .waitForFunction((i) => (document.getElementById(i) as ViewElement).oceano !== null, {}, id)
    .then(() => page.evaluate((i) => (document.getElementById(i) as ViewElement).oceano!.ready, id));

describe('<oceano-view> start-up attributes and events', () => {
  it('starts lazily near the screen, or at once with loading="eager"', async () => {
    const { page } = await openStartup();
    await readyOf(page, 'plain');
    await page.waitForFunction(() =>
      (window as unknown as { __heard: HeardEvent[] }).__heard.some((e) => e.id === 'eagerBelow' && e.type === 'load'),
    );
    // The lazy figure far below has made nothing: no canvas, no context, no events.
    expect(await figureState(page, 'below')).toMatchObject({ api: false, canvas: false });
    expect(await heard(page, 'below')).toEqual([]);
    // Control: the eager one beside it started and drew (and, being far away, then gave its context back).
    expect(await heard(page, 'eagerBelow', 'load')).toHaveLength(1);
  });

  // It also names the figure by its alt.
  it('fires progress up to 1, then load and ready once each, and lets a vertical swipe scroll the page', async () => {
    const { page } = await openStartup();
    await readyOf(page, 'plain');
    const events = await heard(page, 'plain');
    const progress = events.filter((e) => e.type === 'progress').map((e) => e.detail!.totalProgress!);
    expect(progress.length).toBeGreaterThan(1);
    expect(progress).toEqual([...progress].sort((a, b) => a - b));
    expect(progress[progress.length - 1]).toBe(1);
    expect(events.filter((e) => e.type !== 'progress').map((e) => e.type)).toEqual(['load', 'ready']);
    expect(await figureState(page, 'plain')).toMatchObject({ canvas: true, label: 'A swell under a clear sky', touchAction: 'pan-y' });
    // Control: without alt the label says what the figure shows.
    await readyOf(page, 'unnamed');
    expect((await figureState(page, 'unnamed')).label).toBe('Animated 3D ocean under a sky');
  });

  it('orbits a focused figure with the keyboard, and only the focused one', async () => {
    const { page } = await openStartup();
    await readyOf(page, 'plain');
    const camera = () => page.evaluate(() => (document.getElementById('plain') as ViewElement).oceano!.getCamera());
    const before = await camera();
    // Control: the keys pressed with the focus elsewhere on the page leave it alone.
    await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
    await page.keyboard.press('KeyJ');
    expect(await camera()).toEqual(before);
    await page.focus('#plain canvas.oceano-canvas');
    await page.keyboard.press('KeyJ');
    const after = await camera();
    expect(after.target).toEqual(before.target);
    expect(after.position).not.toEqual(before.position);
  });

  it("fires error once for a bad attribute, with the notice's words, and still starts", async () => {
    const { page } = await openStartup();
    await readyOf(page, 'bad');
    const errors = await heard(page, 'bad', 'error');
    expect(errors).toEqual([
      { id: 'bad', type: 'error', detail: { type: 'attribute', message: '"loading=soon" is not one of lazy, eager, auto; using "lazy".' } },
    ]);
    expect(await page.evaluate(() => (document.getElementById('bad') as ViewElement).oceano!.notices())).toEqual([
      errors[0].detail!.message,
    ]);
    // Control: the good figures fired none.
    expect(await heard(page, 'plain', 'error')).toEqual([]);
  });

  it('fires error when the browser takes the context away, and not when the figure gives it back itself', async () => {
    const { page } = await openStartup();
    await readyOf(page, 'unnamed');
    expect(await heard(page, 'unnamed', 'error')).toEqual([]);
    await page.evaluate(() =>
      (document.querySelector('#unnamed canvas') as HTMLCanvasElement)
        .getContext('webgl2')!
        .getExtension('WEBGL_lose_context')!
        .loseContext(),
    );
    await page.waitForFunction(() =>
      (window as unknown as { __heard: HeardEvent[] }).__heard.some((e) => e.id === 'unnamed' && e.type === 'error'),
    );
    const [lost] = await heard(page, 'unnamed', 'error');
    expect(lost.detail!.type).toBe('contextlost');
    expect(lost.detail!.message).toContain('graphics context was lost');
    // The eager figure far below gave its own context back: no error for that.
    expect(await heard(page, 'eagerBelow', 'error')).toEqual([]);
  });

  // A poster with a play button; once activated it draws.
  it('reveal="interaction" stays a poster with no WebGL context until activated from the keyboard', async () => {
    const { page } = await openStartup();
    await readyOf(page, 'plain');
    const waiting = await figureState(page, 'revealed');
    expect(waiting).toMatchObject({
      api: false,
      canvas: false,
      reveal: true,
      poster: { alt: 'The sea, started on request', src: 'favicon.svg' },
    });
    expect(await heard(page, 'revealed')).toEqual([]);
    await page.focus('#revealed .oceano-reveal');
    await page.keyboard.press('Enter');
    await readyOf(page, 'revealed');
    expect(await figureState(page, 'revealed')).toMatchObject({
      api: true,
      canvas: true,
      reveal: false,
      poster: null,
      label: 'The sea, started on request',
    });
    expect((await heard(page, 'revealed', 'load')).length).toBe(1);
  });

  // Last: scrolling down to the lazy figure sends the figures above far away.
  it('applies an attribute changed while the figure is starting, once it is live', async () => {
    const { page } = await openStartup();
    const whileStarting = await page.evaluate(async () => {
      const view = document.getElementById('below') as ViewElement;
      view.scrollIntoView();
      while (!view.oceano) await new Promise((r) => setTimeout(r, 10));
      view.setAttribute('swellamplitude', '3.25');
      return Promise.race([view.oceano.ready.then(() => 'live'), new Promise((r) => setTimeout(() => r('starting'), 0))]);
    });
    expect(whileStarting).toBe('starting');
    await readyOf(page, 'below');
    await page.waitForFunction(() => (document.getElementById('below') as ViewElement).oceano?.getParams().swellAmplitude === 3.25, {
      timeout: 20_000,
    });
    // Control: the figure beside it, never told, keeps the default.
    expect(
      await page.evaluate(() => (document.getElementById('eagerBelow') as ViewElement).oceano?.getParams().swellAmplitude ?? null),
    ).not.toBe(3.25);
  });
});
