import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { LESSONS } from '../../src/app/lessons/lessonCatalog';
import { CONCEPT_PATH, ORDER_NAMES } from '../../src/app/lessons/conceptPath';

const harness = useHarness();

describe('the lessons drawer’s two orders', () => {
  // Control: the report’s order walks the catalogue.
  it('the switch lists the ideas’ order, › and ‹ walk it, and the report’s order comes back', async () => {
    const { page, consoleErrors } = await openOcean(harness, 'lang=es&t=2', 1366, 768);
    await page.waitForSelector('.oceano-lessons-order-option[data-order="ideas"]');
    const listed = () =>
      page.evaluate(() => Array.from(document.querySelectorAll<HTMLElement>('.oceano-lessons-open'), (b) => b.dataset.lesson));
    const opened = async (id: string) => {
      await page.waitForFunction((want) => window.oceano.lesson() === want, { timeout: 10000 }, id).catch(() => undefined);
      return page.evaluate(() => window.oceano.lesson());
    };
    const pressed = () =>
      page.evaluate(() =>
        Array.from(document.querySelectorAll<HTMLElement>('.oceano-lessons-order-option'), (b) => [
          b.textContent,
          b.getAttribute('aria-pressed'),
        ]),
      );
    expect(await listed()).toEqual(LESSONS.map((lesson) => lesson.id));
    expect(await pressed()).toEqual([
      [ORDER_NAMES.report.es, 'true'],
      [ORDER_NAMES.ideas.es, 'false'],
    ]);

    await page.click('.oceano-lessons-order-option[data-order="ideas"]');
    expect(await listed()).toEqual([...CONCEPT_PATH]);
    expect(await pressed()).toEqual([
      [ORDER_NAMES.report.es, 'false'],
      [ORDER_NAMES.ideas.es, 'true'],
    ]);
    await page.click('.oceano-lessons-next');
    expect(await opened(CONCEPT_PATH[0])).toBe(CONCEPT_PATH[0]);
    await page.click('.oceano-lessons-next');
    expect(await opened(CONCEPT_PATH[1])).toBe(CONCEPT_PATH[1]);
    await page.click('.oceano-lessons-previous');
    expect(await opened(CONCEPT_PATH[0])).toBe(CONCEPT_PATH[0]);
    await page.click('.oceano-lessons-next');
    await page.click('.oceano-lessons-next');
    expect(await opened(CONCEPT_PATH[2])).toBe(CONCEPT_PATH[2]);

    // Back to the report's order: › goes to the catalogue's next lesson, not the path's.
    await page.click('.oceano-lessons-all');
    await page.click('.oceano-lessons-order-option[data-order="report"]');
    expect(await listed()).toEqual(LESSONS.map((lesson) => lesson.id));
    await page.click('.oceano-lessons-next');
    const after = LESSONS[LESSONS.findIndex((lesson) => lesson.id === CONCEPT_PATH[2]) + 1].id;
    expect(after).not.toBe(CONCEPT_PATH[3]);
    expect(await opened(after)).toBe(after);
    expect(consoleErrors).toEqual([]);
  });
});
