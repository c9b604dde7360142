import puppeteer, { type Browser, type Page } from 'puppeteer';
import { PNG } from 'pngjs';
import { preview, type PreviewServer } from 'vite';
import { locateBrowser, NO_BROWSER_MESSAGE } from './findBrowser.mjs';

/**
 * Serves the built dist/ on loopback and drives headless Chromium against it. SwiftShader
 * is used so that pictures are the same on every machine, GPU or not. The browser tests use
 * it, and so do the bench and the probes in scripts/, which drive the same built app.
 */
export const BROWSER_ARGS = [
  '--headless=new',
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-gpu-vsync',
  '--hide-scrollbars',
  '--force-color-profile=srgb',
];

export interface Harness {
  browser: Browser;
  baseUrl: string;
  close(): Promise<void>;
}

/**
 * Starts a preview server and a browser, or, given `connectTo` (a running browser's
 * WebSocket endpoint), drives that browser instead: the test suite shares one browser
 * across its files so that its GPU process keeps the shader programs it has compiled.
 * Closing a harness that connected closes the pages it left open and disconnects.
 * The preview server sends vite.config.ts's CROSS_ORIGIN_ISOLATION headers, as `npm start`
 * does: the tests see the page a user of the app's own servers gets.
 */
export async function startHarness(args: string[] = BROWSER_ARGS, connectTo?: string): Promise<Harness> {
  const server: PreviewServer = await preview({ preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'error' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('The preview server has no TCP address.');
  const baseUrl = `http://127.0.0.1:${address.port}/`;
  const browser = connectTo
    ? await puppeteer.connect({ browserWSEndpoint: connectTo })
    : await puppeteer.launch({ executablePath: await findBrowser(), args, headless: true });
  return {
    browser,
    baseUrl,
    async close() {
      if (connectTo) {
        // A page a test left open must not keep the next file's browser busy; one that does
        // not close within seconds (a hung renderer) is left to the browser's own exit.
        const closing = (await browser.pages())
          .filter((page) => page.url() !== 'about:blank')
          .map((page) => page.close().catch(() => undefined));
        await Promise.race([Promise.all(closing), new Promise((resolve) => setTimeout(resolve, 10_000))]);
        await browser.disconnect();
      } else {
        await browser.close();
      }
      // Vite's close drops the open keep-alive connections too: a browser that lives on (the
      // suite's shared one) would otherwise hold the server open until they time out.
      await server.close();
    },
  };
}

export interface OpenedPage {
  page: Page;
  consoleErrors: string[];
}

/**
 * Opens the app with a query string at a size, waits for `oceano.ready`. timeoutMs bounds
 * each wait (puppeteer's default, 30 s, unless given: the benchmark on a busy machine needs more).
 */
export async function openOcean(
  harness: Harness,
  query: string,
  width = 640,
  height = 360,
  path = '',
  timeoutMs?: number,
): Promise<OpenedPage> {
  const page = await harness.browser.newPage();
  if (timeoutMs !== undefined) page.setDefaultTimeout(timeoutMs);
  const consoleErrors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') consoleErrors.push(message.text());
  });
  page.on('pageerror', (error) => consoleErrors.push(String(error)));
  await page.setViewport({ width, height, deviceScaleFactor: 1 });
  // A loaded 2-core machine compiling SwiftShader programs can take longer than puppeteer's 30 s.
  page.setDefaultTimeout(120_000);
  await page.goto(`${harness.baseUrl}${path}${query ? `?${query}` : ''}`, { waitUntil: 'load' });
  await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
  await page.evaluate(() => window.oceano.ready);
  return { page, consoleErrors };
}

/** What is drawn over a canvas (control panel, notices, play button): hidden while a canvas is screenshot. */
const OVERLAYS =
  '.lil-gui, .oceano-notices, .oceano-play, .oceano-fresnel-plot, .oceano-compare, .oceano-lessons, .oceano-lesson-label, .oceano-figure-caption, .oceano-sea-tools, .oceano-ruler-label';

/** Screenshots a canvas element with the overlays above it hidden, so only the ocean is in the picture. */
export async function screenshotCanvas(page: Page, selector = 'canvas'): Promise<Buffer> {
  const canvas = await page.$(selector);
  if (!canvas) throw new Error(`No canvas ${selector} on the page.`);
  await page.evaluate((s) => document.querySelectorAll<HTMLElement>(s).forEach((el) => (el.style.visibility = 'hidden')), OVERLAYS);
  try {
    return Buffer.from(await canvas.screenshot({ type: 'png' }));
  } finally {
    await page.evaluate((s) => document.querySelectorAll<HTMLElement>(s).forEach((el) => (el.style.visibility = '')), OVERLAYS);
  }
}

/** A frame drawn now, then the canvas as PNG bytes (GUI and notices are not in it). */
export async function canvasPng(page: Page): Promise<Buffer> {
  await page.evaluate(() => window.oceano.renderFrame());
  return screenshotCanvas(page);
}

/** The view of `query` opened, drawn and read as a decoded picture, the page closed; a console error throws. */
export async function oceanPicture(harness: Harness, query: string, width?: number, height?: number): Promise<PNG> {
  const { page, consoleErrors } = await openOcean(harness, query, width, height);
  try {
    if (consoleErrors.length) throw new Error(`${query}: ${consoleErrors.join(' / ')}`);
    return PNG.sync.read(await canvasPng(page));
  } finally {
    await page.close();
  }
}

/** The browser the tests drive; findBrowser.mjs says where it is looked for. */
export async function findBrowser(): Promise<string> {
  const found = await locateBrowser();
  if (!found) throw new Error(NO_BROWSER_MESSAGE);
  return found;
}
