import { afterAll } from 'vitest';
import type { Page } from 'puppeteer';
import { openOcean, type Harness, type OpenedPage } from './harness';

export interface SharedPage {
  /** The page (opened on first use), with the console errors it has logged since it loaded. */
  opened(): Promise<OpenedPage>;
  page(): Promise<Page>;
  /**
   * Runs `body` on the page, then puts its parameters, camera and time back as loaded (and
   * the clock paused, as `t=` in the URL leaves it), so the next test sees the loaded view.
   */
  restoring<T>(body: (page: Page) => Promise<T>): Promise<T>;
}

/**
 * One page of a frozen view (the query must give `t=`) for the tests of a file that need no
 * fresh load of their own: each page boot costs seconds of SwiftShader shader compilation and
 * first frames, most of the browser suite's time. Opened by the first test that asks for it
 * (so a test run alone with -t still gets it), closed after the file's tests.
 */
export function sharedPage(harness: Harness, query: string, width?: number, height?: number): SharedPage {
  const time = Number(new URLSearchParams(query).get('t'));
  if (!Number.isFinite(time) || !/(^|&)t=/.test(query)) throw new Error(`sharedPage needs a frozen view (t= in the query): ${query}`);
  let opening: Promise<OpenedPage> | undefined;
  // Brought to the front each time it is handed out: a test may have opened pages of its own
  // since, and a page left in the background draws no frames for screenshots.
  const opened = async () => {
    const o = await (opening ??= openOcean(harness, query, width, height));
    await o.page.bringToFront();
    return o;
  };
  const page = async () => (await opened()).page;
  afterAll(async () => {
    if (opening) await (await opening).page.close();
  });
  return {
    opened,
    page,
    async restoring(body) {
      const p = await page();
      const before = await p.evaluate(() => ({ params: window.oceano.getParams(), camera: window.oceano.getCamera() }));
      try {
        return await body(p);
      } finally {
        await p.evaluate(
          (state, t) => {
            window.oceano.pause();
            window.oceano.setParams(state.params);
            window.oceano.setCamera(state.camera);
            window.oceano.setTime(t);
          },
          before,
          time,
        );
      }
    },
  };
}
