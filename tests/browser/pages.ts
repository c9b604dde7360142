import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'puppeteer';
import { screenshotCanvas, type Harness } from './harness';

const FIXTURE_DIR = join(import.meta.dirname, 'fixtures');

export interface RecordedPage {
  page: Page;
  consoleErrors: string[];
  /** Every URL the page asked for, data: URLs included. */
  requests: string[];
  /** Content-Security-Policy violations reported by the page, as "directive blockedURI". */
  violations: string[];
}

/**
 * A new page that records its requests, errors and CSP violations. `fixtures/NAME` paths
 * are answered from tests/browser/fixtures (as if they were on the preview server, so the
 * same origin as dist/), `block` paths fail like a missing file; the rest goes to the server.
 */
export async function recordedPage(harness: Harness, width: number, height: number, block: string[] = []): Promise<RecordedPage> {
  const page = await harness.browser.newPage();
  const consoleErrors: string[] = [];
  const requests: string[] = [];
  const violations: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') consoleErrors.push(message.text());
  });
  page.on('pageerror', (error) => consoleErrors.push(String(error)));
  await page.exposeFunction('__reportViolation', (text: string) => violations.push(text));
  await page.evaluateOnNewDocument(() => {
    document.addEventListener('securitypolicyviolation', (event) => {
      (window as unknown as { __reportViolation(t: string): void }).__reportViolation(`${event.effectiveDirective} ${event.blockedURI}`);
    });
  });
  await page.setRequestInterception(true);
  page.on('request', (request) => {
    const url = request.url();
    requests.push(url);
    const path = url.startsWith(harness.baseUrl) ? url.slice(harness.baseUrl.length).split('?')[0] : null;
    const fixture = path?.startsWith('fixtures/') ? join(FIXTURE_DIR, path.slice('fixtures/'.length)) : null;
    if (fixture !== null && existsSync(fixture)) {
      const contentType = fixture.endsWith('.css') ? 'text/css' : 'text/html';
      void request.respond({ status: 200, contentType, body: readFileSync(fixture) });
    } else if (fixture !== null) {
      // Answered, never left hanging: a page asking for a file the fixtures lack must see it fail.
      void request.respond({ status: 404, contentType: 'text/plain', body: 'no such fixture' });
    } else if (path !== null && block.includes(path)) {
      void request.respond({ status: 404, contentType: 'text/plain', body: 'missing on purpose' });
    } else {
      void request.continue();
    }
  });
  await page.setViewport({ width, height, deviceScaleFactor: 1 });
  // As openOcean does: a loaded 2-core machine can take longer than puppeteer's 30 s (the
  // ten-figure page's viewsReady waited past 30 s at load 9 in the 11:41 UTC suite run).
  page.setDefaultTimeout(120_000);
  return { page, consoleErrors, requests, violations };
}

/** Resolves once every <oceano-view> on the page has started (they start near the screen) and drawn its first frame. */
export async function viewsReady(page: Page): Promise<void> {
  await page.waitForFunction(() => customElements.get('oceano-view') !== undefined);
  await page.waitForFunction(() =>
    Array.from(document.querySelectorAll('oceano-view')).every((view) => (view as HTMLElement & { oceano: unknown }).oceano),
  );
  await page.evaluate(async () => {
    const views = Array.from(document.querySelectorAll('oceano-view')) as (HTMLElement & {
      oceano: { ready: Promise<void>; loaded(): Promise<void> };
    })[];
    await Promise.all(views.map((view) => view.oceano.ready));
    // The parts fetched on first use (the foam's texture and GLSL) change the picture when they arrive.
    await Promise.all(views.map((view) => view.oceano.loaded()));
  });
}

/** One element's canvas as PNG, drawn now. */
export async function elementCanvasPng(page: Page, selector: string): Promise<Buffer> {
  await page.evaluate(
    (s) => (document.querySelector(s) as HTMLElement & { oceano: { renderFrame(): void } }).oceano.renderFrame(),
    selector,
  );
  return screenshotCanvas(page, `${selector} canvas`);
}
