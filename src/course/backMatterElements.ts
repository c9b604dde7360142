import type { Language } from '../app/language/i18n';
import { BIBLIOGRAPHY, type ReferenceKey } from '../app/lessons/bibliography';
import { GLOSSARY } from '../app/lessons/glossary';
import { firstTermOccurrences } from '../app/lessons/glossaryLinks';
import { citation } from '../app/lessons/referenceLists';
import { LESSON_TEXTS } from '../app/lessons/lessonTexts';
import { citedWorks, glossaryEntries, termAnchor, workAnchor } from './backMatter';

/**
 * The course page's references, bibliography and glossary as elements. Everything is built
 * from text nodes (textContent), so no card's or definition's words are ever read as markup.
 */

const REFERENCES = { es: 'Referencias', en: 'References' } as const;

/** A caption's References fold, like the code quote's: each work in full, linked to its bibliography entry. */
export function referencesFold(keys: readonly ReferenceKey[], language: Language): HTMLDetailsElement {
  const details = document.createElement('details');
  details.className = 'lesson-references';
  const summary = document.createElement('summary');
  summary.textContent = `${REFERENCES[language]} (${keys.length})`;
  const list = document.createElement('ol');
  for (const key of keys) {
    const item = document.createElement('li');
    item.dataset.reference = key;
    const link = document.createElement('a');
    link.href = `#${workAnchor(key)}`;
    link.textContent = citation(BIBLIOGRAPHY[key]);
    item.append(link);
    list.append(item);
  }
  details.append(summary, list);
  return details;
}

/** A card's text as a paragraph whose first occurrence of each glossary term links to its entry (the drawer's rule). */
export function linkedText(className: string, text: string, language: Language): HTMLParagraphElement {
  const p = document.createElement('p');
  p.className = className;
  let at = 0;
  for (const { key, start, end } of firstTermOccurrences(text, language, GLOSSARY)) {
    const link = document.createElement('a');
    link.className = 'glossary-term';
    link.href = `#${termAnchor(key)}`;
    link.dataset.term = key;
    link.textContent = text.slice(start, end);
    p.append(text.slice(at, start), link);
    at = end;
  }
  p.append(text.slice(at));
  return p;
}

/** Fills the page's Bibliography chapter: every work a card cites, each with its id. */
export function writeBibliography(section: HTMLElement): void {
  const list = document.createElement('ol');
  list.className = 'bibliography';
  for (const key of citedWorks(LESSON_TEXTS)) {
    const item = document.createElement('li');
    item.id = workAnchor(key);
    item.dataset.reference = key;
    item.textContent = citation(BIBLIOGRAPHY[key]);
    list.append(item);
  }
  section.append(list);
}

/** Fills the page's Glossary chapter: every term in the page's language, each with its id. */
export function writeGlossary(section: HTMLElement, language: Language): void {
  const list = document.createElement('dl');
  list.className = 'glossary';
  for (const { key, headword, term } of glossaryEntries(language)) {
    const name = document.createElement('dt');
    name.id = termAnchor(key);
    name.dataset.term = key;
    name.textContent = headword;
    const definition = document.createElement('dd');
    definition.textContent = term.definition[language];
    list.append(name, definition);
  }
  section.append(list);
}
