/**
 * `npx tsx scripts/bench/coursePages.ts [dist folder…]`: what a course page of 6, 20 and 30
 * <oceano-view> figures costs with each given build of dist/ (default: dist/). For each page
 * it prints the time until the figures on the first screen are drawn, the time until every
 * figure that starts by itself is drawn, the WebGL contexts alive (and the most at once),
 * the contexts the browser took away, and the JavaScript heap after a garbage collection;
 * then it scrolls to the bottom and back and prints the same again. Figures only, no
 * thresholds: docs/course-pages.md keeps the results.
 */
import { cpSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { BROWSER_ARGS, findBrowser } from '../../tests/browser/harness';
import { serveFolder } from '../../tests/browser/staticServer';
import { presetNames } from '../../src/app/url/presets';

const COUNTS = [6, 20, 30];
const VIEWPORT = { width: 1280, height: 720 };

/** A chapter: one figure per preset (cycled), 320×180, frozen in time, each in a section of text height. */
function chapter(count: number): string {
  const figures = Array.from({ length: count }, (_, i) => `<section><p>Figure ${i + 1}</p><oceano-view preset="${presetNames[i % presetNames.length]}" t="${5 + i}" seed="${1 + i}"></oceano-view></section>`);
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="stylesheet" href="chapter.css"><script type="module" src="oceano.js"></script></head><body>${figures.join('\n')}</body></html>`;
}
const CHAPTER_CSS = 'body { margin: 0; font: 16px sans-serif; } section { height: 420px; } oceano-view { width: 320px; }';

/**
 * Installed before the page's scripts: counts WebGL contexts as they are made, the most alive
 * at once. Text, not a function: tsx would wrap a function's inner functions in a helper
 * the page does not have.
 */
const COUNT_CONTEXTS = `
  const refs = [];
  const seen = new WeakSet();
  const count = { maxLive: 0, live: () => refs.filter((r) => r.deref()?.isContextLost() === false).length };
  window.__contexts = count;
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
    const context = getContext.call(this, type, ...rest);
    if (context && type === 'webgl2' && !seen.has(context)) {
      seen.add(context);
      refs.push(new WeakRef(context));
      count.maxLive = Math.max(count.maxLive, count.live());
    }
    return context;
  };`;

interface Snapshot {
  liveContexts: number;
  maxLiveContexts: number;
  lostByBrowser: number;
  heapMB: number;
}

async function snapshot(page: Page, tooMany: number): Promise<Snapshot> {
  const session = await page.createCDPSession();
  await session.send('HeapProfiler.collectGarbage');
  const { usedSize } = await session.send('Runtime.getHeapUsage');
  await session.detach();
  const counts = (await page.evaluate('({ liveContexts: window.__contexts.live(), maxLiveContexts: window.__contexts.maxLive })')) as { liveContexts: number; maxLiveContexts: number };
  return { ...counts, lostByBrowser: tooMany, heapMB: Math.round(usedSize / 1e5) / 10 };
}

/** Seconds until every figure matching `which` has drawn; `which` runs in the page. */
async function secondsUntilReady(page: Page, since: number, which: string): Promise<number> {
  await page.waitForFunction(`${which}.every((view) => view.oceano)`, { timeout: 600_000 });
  await page.evaluate(`Promise.all(${which}.map((view) => view.oceano.ready))`);
  return Math.round((performance.now() - since) / 100) / 10;
}

const ON_SCREEN = `Array.from(document.querySelectorAll('oceano-view')).filter((v) => { const b = v.getBoundingClientRect(); return b.bottom > 0 && b.top < innerHeight; })`;
/** Figures that start by themselves: every one before lazy loading; those with a context or starting after. */
const STARTED = `Array.from(document.querySelectorAll('oceano-view')).filter((v) => v.oceano || v.querySelector('canvas.oceano-canvas'))`;

async function measure(browser: Browser, url: string, count: number) {
  const page = await browser.newPage();
  page.setDefaultTimeout(600_000);
  await page.setViewport({ ...VIEWPORT, deviceScaleFactor: 1 });
  let tooMany = 0;
  page.on('console', (m) => {
    if (m.text().includes('Too many active WebGL contexts')) tooMany++;
  });
  await page.evaluateOnNewDocument(COUNT_CONTEXTS);
  const start = performance.now();
  await page.goto(url, { waitUntil: 'load' });
  const firstScreenS = await secondsUntilReady(page, start, ON_SCREEN);
  const allStartedS = await secondsUntilReady(page, start, STARTED);
  const loaded = await snapshot(page, tooMany);
  const bottom = (await page.evaluate('document.documentElement.scrollHeight - innerHeight')) as number;
  for (let y = VIEWPORT.height; y < bottom + VIEWPORT.height; y += VIEWPORT.height) {
    await page.evaluate(`window.scrollTo(0, ${Math.min(y, bottom)})`);
    await secondsUntilReady(page, start, ON_SCREEN);
  }
  await page.evaluate('window.scrollTo(0, 0)');
  await secondsUntilReady(page, start, ON_SCREEN);
  const scrolled = await snapshot(page, tooMany);
  await page.close();
  return { count, firstScreenS, allStartedS, loaded, afterScroll: scrolled };
}

async function main(): Promise<void> {
  const builds = process.argv.slice(2);
  if (builds.length === 0) builds.push('dist');
  const browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  try {
    for (const build of builds) {
      const folder = mkdtempSync(join(tmpdir(), 'oceano-chapter-'));
      cpSync(resolve(build), folder, { recursive: true });
      writeFileSync(join(folder, 'chapter.css'), CHAPTER_CSS);
      for (const count of COUNTS) writeFileSync(join(folder, `chapter-${count}.html`), chapter(count));
      const { server, url } = await serveFolder(folder, '/course/');
      try {
        for (const count of COUNTS) console.log(JSON.stringify({ build, ...(await measure(browser, `${url}chapter-${count}.html`, count)) }));
      } finally {
        server.close();
        rmSync(folder, { recursive: true, force: true });
      }
    }
  } finally {
    await browser.close();
  }
}

await main();
