import { LESSON_QUOTES } from 'virtual:oceano-lesson-quotes';
import { LESSON_TEXTS } from '../app/lessons/lessonTexts';
import { LESSON_TITLES } from '../app/lessons/lessonOutline';
import { lessonPoster } from './lessonFigure';
import { linkedText, referencesFold, writeBibliography, writeGlossary } from './backMatterElements';

type Language = 'es' | 'en';

const WORDS = {
  figure: { es: 'Figura', en: 'Figure' },
  code: { es: 'El código', en: 'The code' },
  open: { es: 'Abrir en la aplicación', en: 'Open in the app' },
  question: { es: 'Pregunta', en: 'Question' },
} as const;

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

/**
 * The lesson card's parts, in the page's language: text (its glossary terms linked), the
 * stand-in-or-choice line, equations, question, code, references.
 */
function cardBody(id: string, language: Language): HTMLElement[] {
  const card = LESSON_TEXTS[id];
  const parts: HTMLElement[] = [linkedText('lesson-text', card.text[language], language)];
  if (card.choice) parts.push(element('p', 'lesson-choice', card.choice[language]));
  const math = element('div', 'equation');
  // MathML from the cards' own source (lessonTexts.ts), never from the page's input.
  math.innerHTML = card.math;
  parts.push(math);
  if (card.question) {
    const question = element('details', 'lesson-question');
    question.append(element('summary', '', `${WORDS.question[language]}: ${card.question.ask[language]}`), element('p', '', card.question.answer[language]));
    parts.push(question);
  }
  const quote = LESSON_QUOTES[id];
  if (quote) {
    const details = element('details', 'code-quote');
    const pre = document.createElement('pre');
    pre.append(element('code', '', quote.text));
    details.append(element('summary', '', `${WORDS.code[language]}: ${quote.file}, ${quote.firstLine}–${quote.lastLine}`), pre);
    parts.push(details);
  }
  if (card.references?.length) parts.push(referencesFold(card.references, language));
  return parts;
}

function appLink(id: string, language: Language): HTMLAnchorElement {
  const link = element('a', 'open-in-app', WORDS.open[language]);
  const url = new URL('../index.html', location.href);
  url.searchParams.set('lesson', id);
  url.searchParams.set('lang', language);
  link.href = url.href;
  return link;
}

/**
 * Writes every figure's caption and every linked card from its lesson's card (data-lesson):
 * a figure gets "Figure N." and the title, a card its title as a heading and the lesson's
 * poster; both the card's words, equations, code and references, and a link that opens the
 * lesson. Then the bibliography and glossary chapters the captions link to.
 */
export function writeCaptions(language: Language): void {
  let figures = 0;
  for (const holder of Array.from(document.querySelectorAll<HTMLElement>('[data-lesson]'))) {
    const id = holder.dataset.lesson!;
    const title = LESSON_TITLES[id][language];
    if (holder.localName === 'figure') {
      const caption = holder.querySelector('figcaption') ?? holder.appendChild(document.createElement('figcaption'));
      const heading = element('p', 'lesson-title');
      heading.append(element('strong', '', `${WORDS.figure[language]} ${++figures}.`), ` ${title}`);
      caption.replaceChildren(heading, ...cardBody(id, language), appLink(id, language));
    } else {
      const picture = appLink(id, language);
      picture.className = 'lesson-poster';
      picture.textContent = '';
      const image = element('img', '');
      image.src = lessonPoster(id);
      image.alt = title;
      image.loading = 'lazy';
      image.width = 320;
      image.height = 180;
      // Posters come with `npm run build`; a build without them shows the card without one.
      image.addEventListener('error', () => picture.remove());
      picture.append(image);
      holder.replaceChildren(element('h3', 'lesson-title', title), picture, ...cardBody(id, language), appLink(id, language));
    }
  }
  const bibliography = document.querySelector<HTMLElement>('[data-back-matter="bibliography"]');
  const glossary = document.querySelector<HTMLElement>('[data-back-matter="glossary"]');
  if (bibliography) writeBibliography(bibliography);
  if (glossary) writeGlossary(glossary, language);
  document.documentElement.dataset.captions = 'written';
}
