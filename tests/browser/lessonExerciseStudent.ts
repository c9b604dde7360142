import type { Page } from 'puppeteer';
import { expect } from 'vitest';

/** What the scripted student of the measurement exercises does on a card: open it, answer it. */

/** Types `value` into the open card's exercise, presses Check and answers the verdict line. */
export async function answer(page: Page, value: string): Promise<{ verdict: string; text: string }> {
  await page.$eval('.oceano-lesson-exercise-value', (el) => ((el as HTMLInputElement).value = ''));
  await page.type('.oceano-lesson-exercise-value', value);
  await page.click('.oceano-lesson-exercise-check');
  return page.$eval('.oceano-lesson-exercise-result', (el) => ({
    verdict: (el as HTMLElement).dataset.verdict ?? '',
    text: el.textContent ?? '',
  }));
}

/** Opens lesson `id` and waits for its card with its exercise. */
export async function openLesson(page: Page, id: string): Promise<void> {
  expect(await page.evaluate((lesson) => window.oceano.setLesson(lesson), id)).toBe(true);
  await page.waitForFunction(
    (lesson) =>
      document.querySelector<HTMLElement>('.oceano-lesson-card')?.dataset.lesson === lesson &&
      document.querySelector('.oceano-lesson-exercise') !== null,
    {},
    id,
  );
}
