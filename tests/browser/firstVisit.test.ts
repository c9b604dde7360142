import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { describe, expect, it } from 'vitest';
import { useHarness } from './useHarness';

/** What a first visit sees before the sea: how the page says it cannot start, and its progress while it loads. */
const harness = useHarness();

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
      return {
        isElement: api instanceof Element,
        rejection,
        text: fatal?.innerText ?? '',
        visible: fatal !== null && fatal.getBoundingClientRect().height > 0,
      };
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
    const rejection = await page.evaluate(() =>
      window.oceano.ready.then(
        () => 'resolved',
        (error: Error) => error.message,
      ),
    );
    expect(rejection).toMatch(/WebGL2/);
    expect(await page.$eval('.oceano-fatal', (el) => (el as HTMLElement).innerText)).toBe(rejection);
    await page.close();
  });
});

describe('loading', () => {
  /**
   * Every painted state of the indicator, recorded once per animation frame from before the
   * page's own scripts run: a state that never reaches a frame was never seen by anyone.
   */
  function recordPaintedLoadingStates(): void {
    const seen: string[] = [];
    (window as unknown as { __loadingSeen: string[] }).__loadingSeen = seen;
    const look = () => {
      const box = document.querySelector('.oceano-loading');
      const state = box
        ? Array.from(box.querySelectorAll('li'))
            .map((li) => `${li.dataset.step}:${li.dataset.state}`)
            .join(' ') || 'static'
        : 'none';
      if (seen[seen.length - 1] !== state) seen.push(state);
      requestAnimationFrame(look);
    };
    requestAnimationFrame(look);
  }

  // From the first paint: before the script runs.
  it('shows progress from the first paint, while the first frame is drawn, and while the boat loads', async () => {
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
    page.setDefaultTimeout(120_000);
    await page.evaluateOnNewDocument(recordPaintedLoadingStates);
    const held = new Map<string, () => void>();
    await page.setRequestInterception(true);
    page.on('request', (request) => {
      const url = request.url();
      const which = /\/assets\/index-[^/]*\.js$/.test(url) ? 'script' : url.endsWith('models/boat.glb') ? 'boat' : null;
      if (which) held.set(which, () => void request.continue());
      else void request.continue();
    });
    const opened = page.goto(`${harness.baseUrl}?t=4`, { waitUntil: 'load' });
    await page.waitForFunction(() => document.querySelector('.oceano-loading') !== null);
    await new Promise((resolve) => setTimeout(resolve, 300));
    const beforeScript = await page.evaluate(() => {
      const box = document.querySelector('.oceano-loading') as HTMLElement;
      const r = box.getBoundingClientRect();
      return {
        api: typeof (window as { oceano?: unknown }).oceano,
        text: box.textContent,
        visible: r.width > 50 && r.height > 10 && getComputedStyle(box).visibility === 'visible',
      };
    });
    expect(held.has('script')).toBe(true);
    expect(beforeScript).toEqual({ api: 'undefined', text: 'Loading Oceano…', visible: true });
    held.get('script')!();
    await page.waitForFunction(() => document.querySelector('.oceano-loading li[data-step="boat"][data-state="active"]') !== null);
    const whileBoat = await page.evaluate(() => ({
      steps: Array.from(document.querySelectorAll('.oceano-loading li')).map(
        (li) => `${(li as HTMLElement).dataset.step}:${(li as HTMLElement).dataset.state}`,
      ),
      role: document.querySelector('.oceano-loading')!.getAttribute('role'),
    }));
    expect(whileBoat).toEqual({ steps: ['sky:done', 'firstFrame:done', 'boat:active'], role: 'status' });
    for (let waited = 0; !held.has('boat') && waited < 10_000; waited += 50) await new Promise((resolve) => setTimeout(resolve, 50));
    expect(held.has('boat')).toBe(true);
    held.get('boat')!();
    await opened;
    await page.evaluate(() => window.oceano.ready);
    const painted = await page.evaluate(() => (window as unknown as { __loadingSeen: string[] }).__loadingSeen);
    // The first frame holds the main thread for seconds on a software GPU: its step must have been painted first.
    const firstFrameShown = painted.indexOf('sky:done firstFrame:active boat:pending');
    expect(firstFrameShown).toBeGreaterThan(painted.indexOf('static'));
    expect(painted.indexOf('static')).toBeGreaterThanOrEqual(0);
    expect(painted[painted.length - 1]).toBe('none');
    await page.close();
  });
});
