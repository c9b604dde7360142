/**
 * `npx tsx scripts/bench/coursePages.ts [dist folder…] [--counts=6,20,30]`: what a
 * course page of 6, 20 and 30 <oceano-view> figures costs with each given build of dist/
 * (default: dist/). For each page it prints the time until the figures on the first screen are
 * drawn (`ready`), the time until the first figure's first frame (`load`) and its `ready`, until every
 * figure that starts by itself is drawn, the WebGL contexts alive (and the most at once), the
 * contexts the browser took away, the JavaScript heap after a garbage collection (and less V8's
 * compiled code), and the time to draw every figure on screen once with the GPU (median); then
 * it scrolls to the bottom and back and prints the same again; and the same for the build's
 * course page. Figures only, no thresholds: docs/course-pages.md keeps the results (and how to
 * bring back the shared-renderer prototype this measured beside them).
 */
import { cpSync, existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { BROWSER_ARGS, findBrowser } from '../../tests/browser/harness';
import { serveFolder } from '../../tests/browser/staticServer';
import { presetNames } from '../../src/app/url/presets';
import { heapFigures, heapLessCode } from '../../tests/browser/heapFigures';

const COUNTS = (process.argv.find((a) => a.startsWith('--counts='))?.slice('--counts='.length) ?? '6,20,30')
  .split(',')
  .filter(Boolean)
  .map(Number);
const FRAMES = 9;
const VIEWPORT = { width: 1280, height: 720 };

/** A chapter: one figure per preset (cycled), 320×180, frozen in time, each in a section of text height. */
function chapter(count: number): string {
  const figures = Array.from(
    { length: count },
    (_, i) =>
      `<section><p>Figure ${i + 1}</p><oceano-view preset="${presetNames[i % presetNames.length]}" t="${5 + i}" seed="${1 + i}"></oceano-view></section>`,
  );
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
  heapLessCodeMB: number;
}

async function snapshot(page: Page, tooMany: number): Promise<Snapshot> {
  const session = await page.createCDPSession();
  const heap = await heapFigures(session);
  await session.detach();
  const counts = (await page.evaluate('({ liveContexts: window.__contexts.live(), maxLiveContexts: window.__contexts.maxLive })')) as {
    liveContexts: number;
    maxLiveContexts: number;
  };
  const mb = (bytes: number) => Math.round(bytes / 1e4) / 100;
  return { ...counts, lostByBrowser: tooMany, heapMB: mb(heap.used), heapLessCodeMB: mb(heapLessCode(heap)) };
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

/** Milliseconds to draw every live figure on screen once, each waiting for the GPU (renderFrame), median of FRAMES rounds. */
const ELEMENT_FRAME_MS = `(() => {
  const views = ${ON_SCREEN}.filter((v) => v.oceano);
  const times = [];
  for (let i = 0; i < ${FRAMES}; i++) {
    const start = performance.now();
    for (const view of views) view.oceano.renderFrame();
    times.push(performance.now() - start);
  }
  return Math.round(times.sort((a, b) => a - b)[${Math.floor(FRAMES / 2)}] * 10) / 10;
})()`;

async function openPage(browser: Browser): Promise<{ page: Page; tooMany: () => number }> {
  const page = await browser.newPage();
  page.setDefaultTimeout(600_000);
  await page.setViewport({ ...VIEWPORT, deviceScaleFactor: 1 });
  let tooMany = 0;
  page.on('console', (m) => {
    if (m.text().includes('Too many active WebGL contexts')) tooMany++;
  });
  await page.evaluateOnNewDocument(COUNT_CONTEXTS);
  return { page, tooMany: () => tooMany };
}

async function measure(browser: Browser, url: string, count: number) {
  const { page, tooMany } = await openPage(browser);
  const start = performance.now();
  await page.evaluateOnNewDocument(
    `for (const type of ['load', 'ready']) document.addEventListener(type, (e) => { if (e.target.localName === 'oceano-view') window['__first_' + type] ??= performance.now(); }, true);`,
  );
  await page.goto(url, { waitUntil: 'load' });
  const firstScreenS = await secondsUntilReady(page, start, ON_SCREEN);
  const allStartedS = await secondsUntilReady(page, start, STARTED);
  // The first figure's first frame and its complete picture, from the page's own clock (navigation start).
  const pageSeconds = async (name: string) => Math.round(((await page.evaluate(`window.__first_${name}`)) as number) / 100) / 10;
  const [firstFrameS, firstReadyS] = [await pageSeconds('load'), await pageSeconds('ready')];
  const frameMs = (await page.evaluate(ELEMENT_FRAME_MS)) as number;
  const loaded = await snapshot(page, tooMany());
  const bottom = (await page.evaluate('document.documentElement.scrollHeight - innerHeight')) as number;
  for (let y = VIEWPORT.height; y < bottom + VIEWPORT.height; y += VIEWPORT.height) {
    await page.evaluate(`window.scrollTo(0, ${Math.min(y, bottom)})`);
    await secondsUntilReady(page, start, ON_SCREEN);
  }
  await page.evaluate('window.scrollTo(0, 0)');
  await secondsUntilReady(page, start, ON_SCREEN);
  // Every figure still starting (near the screen, not on it) done too: a start's passing allocations are not what stays.
  await secondsUntilReady(page, start, STARTED);
  const scrolled = await snapshot(page, tooMany());
  await page.close();
  return { count, firstFrameS, firstReadyS, firstScreenS, allStartedS, frameMs, loaded, afterScroll: scrolled };
}

async function main(): Promise<void> {
  const builds = process.argv.slice(2).filter((a) => !a.startsWith('--'));
  if (builds.length === 0) builds.push('dist');
  const browser = await puppeteer.launch({
    executablePath: await findBrowser(),
    args: BROWSER_ARGS,
    headless: true,
    protocolTimeout: 1_200_000,
  });
  try {
    for (const dist of builds) {
      const folder = mkdtempSync(join(tmpdir(), 'oceano-chapter-'));
      cpSync(resolve(dist), folder, { recursive: true });
      writeFileSync(join(folder, 'chapter.css'), CHAPTER_CSS);
      for (const count of COUNTS) writeFileSync(join(folder, `chapter-${count}.html`), chapter(count));
      const { server, url } = await serveFolder(folder, '/course/');
      try {
        for (const count of COUNTS)
          console.log(JSON.stringify({ build: dist, ...(await measure(browser, `${url}chapter-${count}.html`, count)) }));
        // The course page itself (dist/course/, its figures about 640×360), where the build has one.
        if (existsSync(join(folder, 'course', 'index.html'))) {
          const figures = (readFileSync(join(folder, 'course', 'index.html'), 'utf8').match(/<oceano-view /g) ?? []).length;
          console.log(
            JSON.stringify({
              build: dist,
              page: 'course/index.html',
              ...(await measure(browser, `${url}course/index.html?lang=en`, figures)),
            }),
          );
        }
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
