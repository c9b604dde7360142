/**
 * `npm run build` runs this after `vite build`: a poster for every preset and every lesson, the
 * picture a figure with that attribute shows once it is complete (its `ready`: the boat in, and
 * any view whose code comes after the first frame), at time 0, as dist/posters/presets/NAME.webp
 * and dist/posters/lessons/ID.webp. A course page can then write
 * `<oceano-view preset="gale" poster="posters/presets/gale.webp">` and show what the figure is
 * about to draw while it starts. Small (320×180), and quick: one headless Chromium, one page, one
 * figure that is shown each view in turn, so it compiles each shader once (a fresh figure per
 * poster took 5-7 s each on this machine). A lesson that shows a preset's view as it is shares
 * that preset's picture. Without a Chromium the build says so and goes on without posters.
 *
 * `npx tsx scripts/build/posters.ts [dist folder]` (default dist/).
 */
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer, { type Browser } from 'puppeteer';
import { BROWSER_ARGS } from '../../tests/browser/harness';
import { locateBrowser } from '../../tests/browser/findBrowser.mjs';
import { serveFolder } from '../../tests/browser/staticServer';
import { presetNames } from '../../src/app/url/presets';
import * as lessons from '../../src/app/lessons/lessonCatalog';
import { parseSettings, type UrlState } from '../../src/app/url/urlState';

export const POSTER_SIZE = { width: 320, height: 180 };
/** WebP quality: a 320×180 poster of 1 to 17 kB, which the live picture replaces within seconds. */
const QUALITY = 0.8;
const PAGE = 'poster-page.html';

export interface PosterJob {
  /** The figure's attribute and value it stands for: preset="gale", lesson="fresnel". */
  attribute: 'preset' | 'lesson';
  value: string;
  /** Its view, as the attribute sets it. */
  view: Pick<UrlState, 'params' | 'camera' | 'cullingCamera'>;
  /** Where its picture goes, relative to dist/: every preset and lesson that shows the same view. */
  files: string[];
}

/** Every preset and every lesson, one job per distinct view (parameters, camera, culling camera). */
export function posterJobs(): PosterJob[] {
  const byView = new Map<string, PosterJob>();
  const add = (attribute: PosterJob['attribute'], value: string, file: string) => {
    const { params, camera, cullingCamera } = parseSettings([[attribute, value]], lessons);
    const view = { params, camera, cullingCamera };
    const key = JSON.stringify(view);
    const job = byView.get(key);
    if (job) job.files.push(file);
    else byView.set(key, { attribute, value, view, files: [file] });
  };
  for (const name of presetNames) add('preset', name, `posters/presets/${name}.webp`);
  for (const id of lessons.lessonIds) add('lesson', id, `posters/lessons/${id}.webp`);
  return [...byView.values()];
}

/**
 * In a page of dist/ with the element and nothing else: one figure, frozen at time 0, shown a
 * view as the element's start-up sets it (a culling selection frozen where the culling camera
 * stands, and only then the view's camera), its time jumped away and back so that the boat stands on its
 * true pose and the wake is replayed for this view, as in a fresh figure. Once every part the
 * view needs is in, it draws, and the canvas is read in that task (it keeps no drawing after).
 * Text, not a function: tsx wraps a function's inner functions in a helper the page lacks.
 */
const SHOW_VIEW = `async ([view, quality]) => {
  let figure = window.posterFigure;
  if (!figure) {
    figure = window.posterFigure = document.createElement('oceano-view');
    figure.setAttribute('t', '0');
    figure.setAttribute('lang', 'en');
    figure.setAttribute('loading', 'eager');
    document.body.append(figure);
    while (!figure.oceano) await new Promise((resolve) => setTimeout(resolve, 50));
    await figure.oceano.ready;
  }
  const oceano = figure.oceano;
  if (view.cullingCamera && view.params.freezeCulling) {
    oceano.setParams({ ...view.params, freezeCulling: false });
    oceano.setCamera(view.cullingCamera);
    oceano.renderFrame();
    oceano.setParams(view.params);
    oceano.renderFrame();
  }
  oceano.setParams(view.params);
  oceano.setCamera(view.camera);
  oceano.setTime(1000);
  oceano.renderFrame();
  oceano.setTime(0);
  await oceano.loaded();
  oceano.renderFrame();
  return figure.querySelector('canvas.oceano-canvas').toDataURL('image/webp', quality);
}`;

/** Renders the posters with `browser` from the dist/ served at `distUrl`; returns the WebP bytes by file, and the jobs that failed. */
export async function renderPosters(
  browser: Browser,
  distUrl: string,
  jobs: PosterJob[],
): Promise<{ posters: Map<string, Buffer>; failed: string[] }> {
  const page = await browser.newPage();
  const posters = new Map<string, Buffer>();
  const failed: string[] = [];
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(String(error)));
  try {
    await page.setViewport({ ...POSTER_SIZE, deviceScaleFactor: 1 });
    await page.setRequestInterception(true);
    page.on('request', (request) => {
      if (request.url() !== distUrl + PAGE) return void request.continue();
      const body = `<!doctype html><html lang="en"><head><meta charset="utf-8"><script type="module" src="oceano.js"></script>
        <style>body { margin: 0; } oceano-view { width: ${POSTER_SIZE.width}px; }</style></head><body></body></html>`;
      void request.respond({ status: 200, contentType: 'text/html', body });
    });
    page.setDefaultTimeout(120_000);
    await page.goto(distUrl + PAGE, { waitUntil: 'load' });
    await page.waitForFunction(() => customElements.get('oceano-view') !== undefined);
    for (const job of jobs) {
      try {
        const dataUrl = (await page.evaluate(`(${SHOW_VIEW})(${JSON.stringify([job.view, QUALITY])})`)) as string;
        const bytes = Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64');
        for (const file of job.files) posters.set(file, bytes);
      } catch (error) {
        failed.push(`${job.files.join(', ')}: ${error instanceof Error ? error.message : String(error)}`);
      }
    }
  } finally {
    await page.close();
  }
  failed.push(...errors.map((error) => `page error: ${error}`));
  return { posters, failed };
}

/** Renders every poster and writes them into `dist` (served at `distUrl`), in place of any there; says what it did. */
export async function buildPosters(browser: Browser, distUrl: string, dist: string): Promise<string> {
  const started = performance.now();
  const jobs = posterJobs();
  const { posters, failed } = await renderPosters(browser, distUrl, jobs);
  rmSync(join(dist, 'posters'), { recursive: true, force: true });
  for (const [file, bytes] of posters) {
    mkdirSync(dirname(join(dist, file)), { recursive: true });
    writeFileSync(join(dist, file), bytes);
  }
  const kB = [...posters.values()].reduce((sum, bytes) => sum + bytes.length, 0) / 1024;
  const made = `posters: ${posters.size} of ${jobs.flatMap((job) => job.files).length} (${jobs.length} views) in dist/posters/ (${kB.toFixed(0)} kB) in ${((performance.now() - started) / 1000).toFixed(1)} s`;
  return [made, ...failed.map((line) => `posters: not made: ${line}`)].join('\n');
}

async function main(): Promise<void> {
  const dist = resolve(process.argv[2] ?? 'dist');
  const executablePath = await locateBrowser();
  if (!executablePath) {
    console.warn(
      'posters: no Chrome or Chromium found (install chromium, or set CHROME_PATH): the build goes on without posters in dist/posters/.',
    );
    return;
  }
  const { server, url } = await serveFolder(dist, '/');
  const browser = await puppeteer.launch({ executablePath, args: BROWSER_ARGS, headless: true });
  try {
    console.log(await buildPosters(browser, url, dist));
  } finally {
    await browser.close();
    server.close();
  }
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  // A browser that will not start is no reason to fail the build either: it says why and goes on.
  main().catch((error: unknown) =>
    console.warn(`posters: not made (${error instanceof Error ? error.message : String(error)}): the build goes on without them.`),
  );
}
