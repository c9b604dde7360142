import type { Page } from 'puppeteer';

// The <oceano-view> figures whose box overlaps the window, as page-side code.
const ON_SCREEN = `Array.from(document.querySelectorAll('oceano-view')).filter((view) => {
  const box = view.getBoundingClientRect();
  return box.bottom > 0 && box.top < innerHeight;
})`;

/** Waits until every figure on screen has started and drawn (its `ready`); gives how many there are. */
export async function visibleFiguresReady(page: Page): Promise<number> {
  await page.waitForFunction(`${ON_SCREEN}.every((view) => view.oceano !== null)`);
  return page.evaluate(`Promise.all(${ON_SCREEN}.map((view) => view.oceano.ready)).then((all) => all.length)`) as Promise<number>;
}
