import { afterAll, describe, expect, it } from 'vitest';
import { canvasPng, openOcean, screenshotCanvas } from './harness';
import { useHarness } from './useHarness';
import { diffPngs } from './imageCompare';
import { elementCanvasPng, recordedPage, viewsReady, type RecordedPage } from './pages';

const harness = useHarness();

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };

describe('<oceano-view> (dist/oceano.js)', () => {
  it('puts two independent figures on one page under a strict CSP, each equal to the page app with the same settings', async () => {
    const { page, consoleErrors, requests, violations } = await recordedPage(harness, 400, 500);
    await page.goto(`${harness.baseUrl}fixtures/two-views.html`, { waitUntil: 'load' });
    await viewsReady(page);

    const facts = await page.evaluate(() => {
      const [a, b] = Array.from(document.querySelectorAll('oceano-view')) as ViewElement[];
      return {
        separateApis: a.oceano !== b.oceano,
        canvases: document.querySelectorAll('oceano-view canvas').length,
        contexts: Array.from(document.querySelectorAll('canvas'), (c) => c.getContext('webgl2') !== null),
        firstParams: a.oceano!.getParams(),
        secondParams: b.oceano!.getParams(),
        secondLabel: b.querySelector('canvas')!.getAttribute('aria-label'),
        size: [a.clientWidth, a.clientHeight],
        noGlobal: (window as { oceano?: unknown }).oceano === undefined,
        inlineScriptRan: (window as { inlineScriptRan?: boolean }).inlineScriptRan === true,
      };
    });
    expect(facts.separateApis).toBe(true);
    expect(facts.canvases).toBe(2);
    expect(facts.contexts).toEqual([true, true]);
    expect(facts.firstParams.seed).toBe(1);
    expect(facts.secondParams).toMatchObject({ seed: 2, swellAmplitude: 2.5 });
    expect(facts.secondLabel).toBe('Océano 3D animado bajo un cielo');
    expect(facts.size).toEqual([320, 180]);
    expect(facts.noGlobal).toBe(true);
    // The CSP is really enforced: the fixture's one inline script was blocked, and nothing else was.
    expect(facts.inlineScriptRan).toBe(false);
    expect(violations).toEqual(['script-src-elem inline']);
    expect(consoleErrors.filter((e) => !e.includes('Content Security Policy'))).toEqual([]);
    const origin = new URL(harness.baseUrl).origin;
    expect(requests.filter((url) => !url.startsWith('data:')).every((url) => new URL(url).origin === origin)).toBe(true);

    // Changing one figure leaves the other alone.
    const first = await elementCanvasPng(page, '#first');
    const second = await elementCanvasPng(page, '#second');
    expect(diffPngs(first, second).share).toBeGreaterThan(0.03);
    await page.evaluate(() => (document.querySelector('#second') as ViewElement).oceano!.setParams({ seed: 9 }));
    expect(diffPngs(first, await elementCanvasPng(page, '#first'), 0).differentPixels).toBe(0);

    // The same settings in the full page draw the same picture, pixel for pixel.
    const app = await openOcean(harness, 'seed=1&t=10', 320, 180);
    expect(diffPngs(first, await canvasPng(app.page), 0).differentPixels).toBe(0);
    await app.page.close();
    await page.close();
  });

  it('holds ten frozen figures on one page: every context alive, no frame loop running', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 800, 600);
    await page.goto(`${harness.baseUrl}fixtures/ten-views.html`, { waitUntil: 'load' });
    await viewsReady(page);
    const views = await page.evaluate(() =>
      (Array.from(document.querySelectorAll('oceano-view')) as ViewElement[]).map((view) => ({
        lost: view.querySelector('canvas')!.getContext('webgl2')!.isContextLost(),
        looping: view.oceano!.activity().looping,
        seed: view.oceano!.getParams().seed,
      })),
    );
    expect(views).toHaveLength(10);
    expect(views.map((v) => v.seed)).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9, 10]);
    expect(views.every((v) => !v.lost && !v.looping)).toBe(true);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('follows attribute changes, validated like the URL', async () => {
    const { page } = await recordedPage(harness, 400, 500);
    await page.goto(`${harness.baseUrl}fixtures/two-views.html`, { waitUntil: 'load' });
    await viewsReady(page);
    const result = await page.evaluate(() => {
      const view = document.querySelector('#first') as ViewElement;
      view.setAttribute('swellAmplitude', '3.5');
      view.setAttribute('cam', '1,20,30,0,0,-50');
      const camera = view.oceano!.getCamera();
      view.setAttribute('seed', '7');
      view.setAttribute('seed', 'x');
      view.setAttribute('t', '-4');
      return { params: view.oceano!.getParams(), camera, notices: view.oceano!.notices(), looping: view.oceano!.activity().looping };
    });
    expect(result.params).toMatchObject({ swellAmplitude: 3.5, seed: 1 });
    expect(result.camera).toEqual({ position: [1, 20, 30], target: [0, 0, -50] });
    expect(result.looping).toBe(true);
    expect(result.notices).toEqual([
      '"seed=x" is not an integer; using the default 1.',
      '"t=-4" is not a time in seconds between 0 and 1e9; the animation runs from 0 instead.',
    ]);
    await page.close();
  });

  /**
   * far-apart.html (two figures, the second, loading="eager", far below the first) loaded
   * once for the two tests that look at it: each boot of its figures costs seconds of
   * SwiftShader work.
   */
  let farApart: Promise<RecordedPage> | undefined;
  const openFarApart = async () => {
    const recorded = await (farApart ??= recordedPage(harness, 400, 400).then(async (opened) => {
      await opened.page.goto(`${harness.baseUrl}fixtures/far-apart.html`, { waitUntil: 'load' });
      await opened.page.waitForFunction(() => customElements.get('oceano-view') !== undefined);
      return opened;
    }));
    // Pages opened since leave this one in the background, where no frames are drawn.
    await recorded.page.bringToFront();
    return recorded;
  };
  afterAll(async () => {
    if (farApart) await (await farApart).page.close();
  });

  it('gives the context of a figure far from the screen back, keeping its last frame, and brings it back live', async () => {
    const { page, consoleErrors } = await openFarApart();
    const state = (selector: string) =>
      page.evaluate((s) => {
        const view = document.querySelector(s) as ViewElement;
        return {
          live: view.oceano !== null,
          webgl: view.querySelector('canvas.oceano-canvas') !== null,
          still: view.querySelector('canvas.oceano-still') !== null,
          activity: view.oceano?.activity() ?? null,
        };
      }, selector);
    // The eager figure started at once, drew, and, being far away, gave its context back.
    await page.waitForFunction(() => (document.querySelector('#far') as ViewElement).querySelector('.oceano-still') !== null);
    expect(await state('#far')).toEqual({ live: false, webgl: false, still: true, activity: null });
    await page.waitForFunction(() => (document.querySelector('#near') as ViewElement).oceano?.activity().looping === true);
    const before = (await state('#near')).activity!;
    await new Promise((r) => setTimeout(r, 1500));
    expect((await state('#near')).activity!.framesDrawn).toBeGreaterThan(before.framesDrawn);

    await page.evaluate(() => document.querySelector('#far')!.scrollIntoView());
    await page.waitForFunction(() => (document.querySelector('#far') as ViewElement).oceano?.activity().looping === true);
    const farFrames = (await state('#far')).activity!.framesDrawn;
    await page.waitForFunction((n) => (document.querySelector('#far') as ViewElement).oceano!.activity().framesDrawn > n, {}, farFrames);
    // The still gives way once the live picture is complete (ready), which may come after a first frame.
    await page.waitForFunction(() => document.querySelector('#far .oceano-still') === null);
    expect(await state('#far')).toMatchObject({ live: true, webgl: true, still: false });
    // The first figure, now far above, has given its context back in turn.
    await page.waitForFunction(() => (document.querySelector('#near') as ViewElement).oceano === null);
    expect(await state('#near')).toMatchObject({ live: false, webgl: false, still: true });
    expect(consoleErrors).toEqual([]);
  });

  it('runs no frame loop for a frozen figure (t given) until it is played', async () => {
    const { page } = await recordedPage(harness, 400, 500);
    await page.goto(`${harness.baseUrl}fixtures/two-views.html`, { waitUntil: 'load' });
    await viewsReady(page);
    const first = () => page.evaluate(() => (document.querySelector('#first') as ViewElement).oceano!.activity());
    const before = await first();
    await new Promise((r) => setTimeout(r, 800));
    expect(await first()).toEqual(before);
    expect(before.looping).toBe(false);
    await page.click('#first .oceano-play');
    await page.waitForFunction(
      (n) => (document.querySelector('#first') as ViewElement).oceano!.activity().framesDrawn > n + 1,
      {},
      before.framesDrawn,
    );
    expect((await first()).looping).toBe(true);
    await page.close();
  });

  it('pauses every figure while the tab is hidden', async () => {
    const { page } = await openFarApart();
    const looping = () => page.evaluate(() => (document.querySelector('#near') as ViewElement).oceano!.activity().looping);
    // The page as loaded: the near figure in view (the scrolling test above leaves the far one there, and this one comes back).
    await page.evaluate(() => document.querySelector('#near')!.scrollIntoView());
    await page.waitForFunction(() => (document.querySelector('#near') as ViewElement).oceano?.activity().looping === true);
    expect(await looping()).toBe(true);
    const setHidden = (hidden: boolean) =>
      page.evaluate((h) => {
        Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => (h ? 'hidden' : 'visible') });
        document.dispatchEvent(new Event('visibilitychange'));
      }, hidden);
    await setHidden(true);
    expect(await looping()).toBe(false);
    await setHidden(false);
    expect(await looping()).toBe(true);
  });

  it('releases the WebGL context and its API when the element is removed', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 400, 500);
    await page.goto(`${harness.baseUrl}fixtures/two-views.html`, { waitUntil: 'load' });
    await viewsReady(page);
    // The second figure at a fixed time, drawn before the first is removed.
    await page.evaluate(() => {
      const o = (document.querySelector('#second') as ViewElement).oceano!;
      o.pause();
      o.setTime(10);
    });
    const secondBefore = await elementCanvasPng(page, '#second');
    const result = await page.evaluate(() => {
      const view = document.querySelector('#first') as ViewElement;
      const gl = view.querySelector('canvas')!.getContext('webgl2')!;
      view.remove();
      return { lost: gl.isContextLost(), api: view.oceano, children: view.childElementCount };
    });
    expect(result).toEqual({ lost: true, api: null, children: 0 });
    // The other figure still draws, the very same picture as before.
    const secondAfter = await elementCanvasPng(page, '#second');
    expect(diffPngs(secondBefore, secondAfter, 0).differentPixels).toBe(0);
    // Negative control: a figure that stopped drawing (its canvas cleared) would not pass that.
    await page.evaluate(() => {
      const gl = (document.querySelector('#second canvas') as HTMLCanvasElement).getContext('webgl2')!;
      gl.clearColor(0, 0, 0, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
    });
    expect(diffPngs(secondBefore, await screenshotCanvas(page, '#second canvas'), 0).differentPixels).toBeGreaterThan(1000);
    expect(consoleErrors.filter((e) => !e.includes('Content Security Policy'))).toEqual([]);
    await page.close();
  });
});
