import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { LESSONS, lessonIds } from '../../src/app/lessons/lessonCatalog';
import { LESSON_TEXTS } from '../../src/app/lessons/lessonTexts';
import { readLessonQuotes } from '../../scripts/build/lessonQuotes';
import { lessonViewAttributes } from '../../src/course/lessonFigure';
import { bannedSpanishWords, pageLessonIds, shownLessonFaults, type CardSource } from '../../src/course/coursePageChecks';

const root = resolve(import.meta.dirname, '..', '..');
const html = readFileSync(resolve(root, 'course/index.html'), 'utf8');
const quotes = readLessonQuotes(root);
const cards = (language: 'es' | 'en'): CardSource => ({ text: (id) => LESSON_TEXTS[id].text[language], code: (id) => quotes[id]?.text ?? null });
/** The page's own Spanish prose: its class="es" elements, tags and entities aside. */
const spanishProse = (page: string) => Array.from(page.matchAll(/<(\w+) class="es">([\s\S]*?)<\/\1>/g), (m) => m[2].replace(/<[^>]+>/g, ' ')).join('\n');

describe('the course page (course/index.html)', () => {
  it('names every lesson of the catalog once, and nothing else', () => {
    const ids = pageLessonIds(html);
    expect([...ids].sort()).toEqual([...lessonIds].sort());
    // Control: a page that drops a lesson, or names one twice, does not pass.
    const dropped = pageLessonIds(html.replace('data-lesson="iwave-boat"', 'data-lesson="iwave-stone"'));
    expect([...dropped].sort()).not.toEqual([...lessonIds].sort());
  });

  it('gives each figure its own lesson\'s view, and a figure pointed at another lesson fails the check', () => {
    for (const lesson of LESSONS) {
      const shown = { lesson: lesson.id, text: LESSON_TEXTS[lesson.id].text.es, code: quotes[lesson.id]?.text ?? null, attributes: lessonViewAttributes(lesson) };
      expect(shownLessonFaults(shown, cards('es'))).toEqual([]);
    }
    // Control: every figure relabelled with the next lesson's id (its view, text and code left as they were) is caught.
    LESSONS.forEach((lesson, i) => {
      const other = LESSONS[(i + 1) % LESSONS.length];
      const shown = { lesson: other.id, text: LESSON_TEXTS[lesson.id].text.es, code: quotes[lesson.id]?.text ?? null, attributes: lessonViewAttributes(lesson) };
      const faults = shownLessonFaults(shown, cards('es'));
      expect(faults.some((f) => f.includes('code') || f.includes('parameters') || f.includes('camera'))).toBe(true);
      expect(faults.some((f) => f.includes('text'))).toBe(true);
    });
  });

  it('writes its own Spanish in one register', () => {
    expect(bannedSpanishWords(spanishProse(html))).toEqual([]);
    // Control: each banned word is found in a sentence, and its right word is not.
    expect(bannedSpanishWords('La grilla del bote, el rolido y las perillas.')).toEqual(['grilla', 'bote', 'rolido', 'perillas']);
    expect(bannedSpanishWords('La malla del barco, el balanceo, los controles y un rebote.')).toEqual([]);
    // The report's own title, quoted, is a citation; the same words unquoted are not.
    expect(bannedSpanishWords('El “Quiero mover el bote” del informe.')).toEqual([]);
    expect(bannedSpanishWords('Quiero mover el bote.')).toEqual(['bote']);
  });
});
