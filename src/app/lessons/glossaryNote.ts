import type { Language, Translator } from '../language/i18n';
import { teachingWord } from '../language/teachingWords';
import { GLOSSARY, type GlossaryKey } from './glossary';
import { firstTermOccurrences } from './glossaryLinks';

/**
 * A card's text with its glossary terms as buttons, and the one note under it that shows
 * the definition of the term last pressed: a second press, or Escape, closes it. Built from
 * text nodes only, so nothing in a card's text is ever read as markup.
 */
export class GlossaryNote {
  readonly element: HTMLElement;
  private readonly term: HTMLElement;
  private readonly definition: HTMLElement;
  private openedBy: HTMLButtonElement | null = null;

  constructor(
    private readonly tr: Translator,
    id: string,
  ) {
    this.element = document.createElement('p');
    this.element.className = 'oceano-lesson-term-note';
    this.element.id = id;
    this.element.setAttribute('role', 'note');
    this.element.setAttribute('aria-live', 'polite');
    this.element.hidden = true;
    this.term = document.createElement('dfn');
    this.term.className = 'oceano-lesson-term-name';
    this.definition = document.createElement('span');
    this.element.append(this.term, ' ', this.definition);
  }

  /** `text` as a paragraph whose first occurrence of each glossary term is a button. */
  paragraph(className: string, text: string): HTMLParagraphElement {
    const language: Language = this.tr.language;
    const p = document.createElement('p');
    p.className = className;
    let at = 0;
    for (const { key, start, end } of firstTermOccurrences(text, language, GLOSSARY)) {
      p.append(text.slice(at, start));
      p.append(this.termButton(key as GlossaryKey, text.slice(start, end)));
      at = end;
    }
    p.append(text.slice(at));
    return p;
  }

  private termButton(key: GlossaryKey, words: string): HTMLButtonElement {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'oceano-lesson-term';
    b.textContent = words;
    b.dataset.term = key;
    b.title = teachingWord(this.tr, 'glossaryTermHint').replace('{term}', GLOSSARY[key].words[this.tr.language][0]);
    b.setAttribute('aria-expanded', 'false');
    b.setAttribute('aria-controls', this.element.id);
    b.addEventListener('click', () => (this.openedBy === b ? this.close(false) : this.open(b, key)));
    return b;
  }

  private open(b: HTMLButtonElement, key: GlossaryKey): void {
    this.openedBy?.setAttribute('aria-expanded', 'false');
    this.openedBy = b;
    b.setAttribute('aria-expanded', 'true');
    const term = GLOSSARY[key];
    this.term.textContent = `${term.words[this.tr.language][0]}:`;
    this.definition.textContent = term.definition[this.tr.language];
    this.element.dataset.term = key;
    this.element.hidden = false;
    // On a phone's short sheet the note can open below the fold: bring it into sight, no further.
    this.element.scrollIntoView({ block: 'nearest' });
  }

  /** Closes the note; true if it was open. With `refocus`, the focus returns to the term that opened it. */
  close(refocus: boolean): boolean {
    const b = this.openedBy;
    if (!b) return false;
    b.setAttribute('aria-expanded', 'false');
    this.openedBy = null;
    this.element.hidden = true;
    delete this.element.dataset.term;
    if (refocus) b.focus();
    return true;
  }
}
