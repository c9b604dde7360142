import type { Language } from '../app/language/i18n';
import { bySurnameAndYear, type ReferenceKey } from '../app/lessons/bibliography';
import { GLOSSARY, type GlossaryKey, type GlossaryTerm } from '../app/lessons/glossary';
import type { LessonText } from '../app/lessons/lessonTexts';

/**
 * The course page's back matter as data: which works its bibliography lists and in what
 * order, the glossary's order in a language, and the ids captions link to. No DOM, so the
 * unit tests and the page share one rule.
 */

/** The bibliography entry's id: a caption's reference links to it. */
export const workAnchor = (key: string): string => `work-${key}`;
/** The glossary entry's id: a term in a caption's text links to it. */
export const termAnchor = (key: string): string => `term-${key}`;

/** Every work some card cites, once each, by first author's surname and year (as the app's bibliography). */
export function citedWorks(cards: Record<string, LessonText>): ReferenceKey[] {
  return bySurnameAndYear([...new Set(Object.values(cards).flatMap((card) => card.references ?? []))]);
}

/** Every glossary term with its headword in `language`, in that language's alphabetical order. */
export function glossaryEntries(language: Language): { key: GlossaryKey; headword: string; term: GlossaryTerm }[] {
  return (Object.entries(GLOSSARY) as [GlossaryKey, GlossaryTerm][])
    .map(([key, term]) => ({ key, headword: term.words[language][0], term }))
    .sort((a, b) => a.headword.localeCompare(b.headword, language, { sensitivity: 'base' }));
}
