import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { useHarness } from './useHarness';

/** The page runs under a strict content security policy, as a host site may serve it. */
const harness = useHarness();

describe('content security policy', () => {
  const STRICT = "default-src 'self'; style-src 'self' 'unsafe-inline'";

  it(`runs clean under "${STRICT}", the panel's icon font included`, async () => {
    const html = readFileSync(join(import.meta.dirname, '..', '..', 'dist', 'index.html'), 'utf8');
    const strict = html.replace(
      /<meta http-equiv="Content-Security-Policy" content="[^"]*"/,
      `<meta http-equiv="Content-Security-Policy" content="${STRICT}"`,
    );
    expect(strict).toContain(STRICT);
    const page = await harness.browser.newPage();
    const violations: string[] = [];
    const errors: string[] = [];
    const requests: string[] = [];
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.exposeFunction('__violation', (text: string) => violations.push(text));
    await page.evaluateOnNewDocument(() => {
      document.addEventListener('securitypolicyviolation', (e) =>
        (window as unknown as { __violation(t: string): void }).__violation(`${e.effectiveDirective} ${e.blockedURI}`),
      );
    });
    await page.setRequestInterception(true);
    page.on('request', (request) => {
      requests.push(request.url());
      if (request.url().split('?')[0] === harness.baseUrl) void request.respond({ status: 200, contentType: 'text/html', body: strict });
      else void request.continue();
    });
    await page.setViewport({ width: 800, height: 600, deviceScaleFactor: 1 });
    await page.goto(`${harness.baseUrl}?t=1`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    // A checked box draws its ✓ in lil-gui's icon font: make sure the font is wanted and loaded.
    await page.evaluate(() =>
      document
        .querySelectorAll<HTMLElement>('.lil-gui .lil-title')
        .forEach((t) => t.parentElement!.classList.contains('lil-closed') && t.click()),
    );
    const fontLoaded = await page.evaluate(async () => {
      await document.fonts.ready;
      return (
        document.fonts.check('12px "lil-gui"', '✓') &&
        Array.from(document.fonts).some((f) => f.family.replaceAll('"', '') === 'lil-gui' && f.status === 'loaded')
      );
    });
    expect(violations).toEqual([]);
    expect(errors).toEqual([]);
    expect(fontLoaded).toBe(true);
    expect(requests.some((url) => url.endsWith('fonts/lil-gui.woff2'))).toBe(true);
    await page.close();
  });
});
