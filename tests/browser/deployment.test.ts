import { describe, expect, it } from 'vitest';
import { createServer, type Server } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';
import puppeteer from 'puppeteer';
import { BROWSER_ARGS, findBrowser } from './harness';
import { useHarness } from './useHarness';

const DIST = join(import.meta.dirname, '..', '..', 'dist');
const SUB_PATH = '/courses/graphics/week-3/ocean/';
const TYPES: Record<string, string> = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.glb': 'model/gltf-binary',
};

/** A plain static file server that puts dist/ under a deep sub-path, as a course site would. */
function serveUnderSubPath(): Promise<{ server: Server; url: string }> {
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://x').pathname);
    if (!path.startsWith(SUB_PATH)) {
      response.writeHead(404).end();
      return;
    }
    const relative = normalize(path.slice(SUB_PATH.length) || 'index.html');
    try {
      const body = await readFile(join(DIST, relative));
      response.writeHead(200, { 'content-type': TYPES[extname(relative)] ?? 'application/octet-stream' }).end(body);
    } catch {
      response.writeHead(404).end();
    }
  });
  return new Promise((resolve) =>
    server.listen(0, '127.0.0.1', () => {
      const address = server.address();
      const port = typeof address === 'object' && address ? address.port : 0;
      resolve({ server, url: `http://127.0.0.1:${port}${SUB_PATH}` });
    }),
  );
}

describe('deployment', () => {
  const harness = useHarness();

  it('works from a static copy of dist/ under any sub-path (relative base)', async () => {
    const { server, url } = await serveUnderSubPath();
    const page = await harness.browser.newPage();
    const failed: string[] = [];
    page.on('response', (response) => {
      if (response.status() >= 400) failed.push(`${response.status()} ${response.url()}`);
    });
    try {
      await page.setViewport({ width: 320, height: 180 });
      await page.goto(`${url}?t=3`, { waitUntil: 'load' });
      await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
      await page.evaluate(() => window.oceano.ready);
      expect(failed).toEqual([]);
      expect(await page.evaluate(() => window.oceano.notices())).toEqual([]);
    } finally {
      await page.close();
      server.close();
    }
  });

  it('tells a browser without WebGL2 so, in words, instead of a blank page', async () => {
    const browser = await puppeteer.launch({ executablePath: await findBrowser(), args: [...BROWSER_ARGS, '--disable-webgl', '--disable-webgl2'] });
    try {
      const page = await browser.newPage();
      const errors: string[] = [];
      page.on('pageerror', (error) => errors.push(String(error)));
      await page.goto(harness.baseUrl, { waitUntil: 'load' });
      await page.waitForSelector('.oceano-fatal');
      const text = await page.$eval('.oceano-fatal', (el) => (el as HTMLElement).innerText);
      expect(text).toMatch(/WebGL2/);
      expect(errors).toEqual([]);
    } finally {
      await browser.close();
    }
  });
});
