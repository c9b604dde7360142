import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Browser, Page } from 'puppeteer';
import { build, preview } from 'vite';

/** Where the copy of three.js's ocean example lives (see its main.ts for what it is and is not). */
const PAGE_ROOT = 'scripts/bench/threejsOcean';

export interface ExampleServer {
  baseUrl: string;
  close(): Promise<void>;
}

/**
 * Builds the three.js ocean example page with the installed `three` (minified, like the
 * app's dist/) into a temporary folder and serves it on loopback with the same headers as
 * the app, so both are timed the same way. Vite's own config (the app's) is not used.
 */
export async function serveThreejsOceanExample(headers: Record<string, string>): Promise<ExampleServer> {
  const outDir = mkdtempSync(join(tmpdir(), 'oceano-threejs-ocean-'));
  const common = { configFile: false as const, root: PAGE_ROOT, base: './', logLevel: 'warn' as const };
  await build({ ...common, build: { outDir, emptyOutDir: true, reportCompressedSize: false } });
  const server = await preview({ ...common, build: { outDir }, preview: { port: 0, host: '127.0.0.1', strictPort: false, headers } });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('The three.js example server has no TCP address.');
  return {
    baseUrl: `http://127.0.0.1:${address.port}/`,
    async close() {
      await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
      rmSync(outDir, { recursive: true, force: true });
    },
  };
}

/**
 * Opens the example page (`query`: '' or e.g. 'bloom=0') at `width`×`height` and waits for its
 * `window.threejsOcean`; `errors` collects what the page logs as an error from then on.
 */
export async function openThreejsOceanExample(
  browser: Browser,
  baseUrl: string,
  query: string,
  width: number,
  height: number,
  timeoutMs: number,
): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.newPage();
  page.setDefaultTimeout(timeoutMs);
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(String(error)));
  await page.setViewport({ width, height, deviceScaleFactor: 1 });
  await page.goto(`${baseUrl}${query ? `?${query}` : ''}`, { waitUntil: 'load' });
  await page.waitForFunction(() => (window as { threejsOcean?: unknown }).threejsOcean !== undefined);
  return { page, errors };
}
