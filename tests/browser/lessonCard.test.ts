import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { LESSONS } from '../../src/app/lessons/lessonCatalog';
import { LESSON_TEXTS } from '../../src/app/lessons/lessonTexts';
import { BIBLIOGRAPHY, type ReferenceKey } from '../../src/app/lessons/bibliography';
import { GLOSSARY, type GlossaryKey } from '../../src/app/lessons/glossary';
import { citation } from '../../src/app/lessons/referenceLists';

const harness = useHarness();

/** A lesson whose card asks a question and cites works, and one without a choice line, from the cards themselves. */
const asking = LESSONS.find((lesson) => LESSON_TEXTS[lesson.id].question && (LESSON_TEXTS[lesson.id].references?.length ?? 0) > 0)!.id;
const choosing = LESSONS.find((lesson) => LESSON_TEXTS[lesson.id].choice)!.id;
const plain = LESSONS.find((lesson) => !LESSON_TEXTS[lesson.id].choice)!.id;

/** What the reader sees of the open card now (innerText leaves out what is hidden). */
function seen(page: Page) {
  return page.evaluate(() => {
    const card = document.querySelector<HTMLElement>('.oceano-lesson-card')!;
    const reveal = card.querySelector<HTMLButtonElement>('.oceano-lesson-reveal');
    const note = card.querySelector<HTMLElement>('.oceano-lesson-term-note')!;
    return {
      lesson: window.oceano.lesson(),
      card: card.innerText,
      text: card.querySelector('.oceano-lesson-text')!.textContent,
      expanded: reveal?.getAttribute('aria-expanded'),
      controls: reveal ? document.getElementById(reveal.getAttribute('aria-controls')!)?.className : undefined,
      note: note.getBoundingClientRect().height > 0 ? note.innerText : '',
      focused: document.activeElement?.className,
    };
  });
}

describe('the lesson card: question, choice, references, glossary', () => {
  // Control: the answer is not on the page before.
  it('hides the answer until its button is pressed, and again when another lesson opens', async () => {
    expect(asking).toBeDefined();
    const words = LESSON_TEXTS[asking];
    const { page, consoleErrors } = await openOcean(harness, `lesson=${asking}&t=2`, 1366, 768);
    await page.waitForSelector('.oceano-lesson-card:not([hidden]) .oceano-lesson-question');
    let facts = await seen(page);
    expect(facts.card).toContain('Before you touch anything');
    expect(facts.card).toContain(words.question!.ask.en);
    expect(facts.card).not.toContain(words.question!.answer.en);
    expect(facts.expanded).toBe('false');
    expect(facts.controls).toBe('oceano-lesson-answer');
    // The question comes before the text: right under the title.
    expect(facts.card.indexOf(words.question!.ask.en)).toBeLessThan(facts.card.indexOf(words.text.en.slice(0, 30)));
    // By keyboard: focus the button, Enter.
    await page.focus('.oceano-lesson-reveal');
    await page.keyboard.press('Enter');
    facts = await seen(page);
    expect(facts.card).toContain(words.question!.answer.en);
    expect(facts.expanded).toBe('true');
    // Another lesson and back: the answer is hidden again.
    await page.keyboard.press('ArrowRight');
    expect((await seen(page)).lesson).not.toBe(asking);
    await page.keyboard.press('ArrowLeft');
    facts = await seen(page);
    expect(facts.lesson).toBe(asking);
    expect(facts.card).not.toContain(words.question!.answer.en);
    expect(facts.expanded).toBe('false');
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  // Each reference in full from the bibliography (control: a card without a choice shows none).
  it('folds the card’s references, each in full, and marks a choice line where the card has one', async () => {
    const keys = LESSON_TEXTS[asking].references as ReferenceKey[];
    const { page } = await openOcean(harness, `lesson=${asking}&t=2`, 1366, 768);
    await page.waitForSelector('.oceano-lesson-card:not([hidden]) .oceano-lesson-references');
    const visibleItems = () =>
      page.evaluate(() =>
        Array.from(document.querySelectorAll<HTMLElement>('.oceano-lesson-reference-list li'), (li) =>
          li.checkVisibility() ? li.textContent : null,
        ).filter((t) => t !== null),
      );
    expect(await visibleItems()).toEqual([]);
    await page.click('.oceano-lesson-references summary');
    expect(await visibleItems()).toEqual(keys.map((key) => citation(BIBLIOGRAPHY[key])));
    await page.evaluate((id) => window.oceano.setLesson(id), plain);
    await page.waitForFunction((id) => document.querySelector<HTMLElement>('.oceano-lesson-card')?.dataset.lesson === id, {}, plain);
    expect(await page.$('.oceano-lesson-choice')).toBeNull();
    await page.evaluate((id) => window.oceano.setLesson(id), choosing);
    await page.waitForSelector('.oceano-lesson-choice');
    const choice = await page.$eval('.oceano-lesson-choice', (p) => (p as HTMLElement).innerText);
    expect(choice).toBe(`A choice, not physics: ${LESSON_TEXTS[choosing].choice!.en}`);
    await page.close();
  });

  // The definition shows in the card (control: closed before the press).
  it('a glossary term in the text shows its definition; a second press or Escape closes it', async () => {
    const { page, consoleErrors } = await openOcean(harness, `lesson=${asking}&lang=es&t=2`, 1366, 768);
    await page.waitForSelector('.oceano-lesson-card:not([hidden]) .oceano-lesson-term');
    let facts = await seen(page);
    // The text is whole: the terms are buttons inside it, not words taken out.
    expect(facts.text).toBe(LESSON_TEXTS[asking].text.es);
    expect(facts.note).toBe('');
    const key = (await page.$eval('.oceano-lesson-text .oceano-lesson-term', (b) => (b as HTMLElement).dataset.term)) as GlossaryKey;
    expect(GLOSSARY[key]).toBeDefined();
    await page.click('.oceano-lesson-text .oceano-lesson-term');
    facts = await seen(page);
    expect(facts.note).toContain(GLOSSARY[key].definition.es);
    expect(facts.lesson).toBe(asking);
    await page.click('.oceano-lesson-text .oceano-lesson-term');
    expect((await seen(page)).note).toBe('');
    await page.click('.oceano-lesson-text .oceano-lesson-term');
    expect((await seen(page)).note).not.toBe('');
    await page.keyboard.press('Escape');
    facts = await seen(page);
    expect(facts.note).toBe('');
    expect(facts.focused).toBe('oceano-lesson-term');
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('the list leads to a bibliography and a glossary in the page’s language, by keyboard, and back to the list', async () => {
    const { page, consoleErrors } = await openOcean(harness, 'lang=es&t=2', 1366, 768);
    await page.waitForSelector('.oceano-lessons-extra[data-view="bibliography"]');
    const view = () =>
      page.evaluate(() => {
        const v = document.querySelector<HTMLElement>('.oceano-lessons-view')!;
        return {
          shown: v.getBoundingClientRect().height > 0,
          listShown: document.querySelector('.oceano-lessons-list')!.getBoundingClientRect().height > 0,
          title: v.querySelector('.oceano-lessons-view-title')?.textContent,
          works: Array.from(v.querySelectorAll('.oceano-bibliography-list li'), (li) => li.textContent),
          terms: Array.from(v.querySelectorAll('.oceano-glossary-list dt'), (dt) => dt.textContent),
          focused: document.activeElement?.className,
        };
      });
    expect((await view()).shown).toBe(false);
    await page.focus('.oceano-lessons-extra[data-view="bibliography"]');
    await page.keyboard.press('Enter');
    let facts = await view();
    expect(facts).toMatchObject({ shown: true, listShown: false, title: 'Bibliografía', focused: 'oceano-lessons-view-title' });
    expect([...facts.works].sort()).toEqual(Object.values(BIBLIOGRAPHY).map(citation).sort());
    await page.click('.oceano-lessons-back');
    facts = await view();
    expect(facts).toMatchObject({ shown: false, listShown: true, focused: 'oceano-lessons-extra' });
    await page.focus('.oceano-lessons-extra[data-view="glossary"]');
    await page.keyboard.press('Enter');
    facts = await view();
    expect(facts.title).toBe('Glosario');
    expect(facts.terms).toHaveLength(Object.keys(GLOSSARY).length);
    expect(facts.terms).toContain('mapa de alturas');
    expect(facts.terms).not.toContain('heightmap');
    // Alphabetical in Spanish.
    expect(facts.terms).toEqual([...facts.terms].sort((a, b) => a!.localeCompare(b!, 'es', { sensitivity: 'base' })));
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
