import './course.css';
import { LESSON_QUOTES } from 'virtual:oceano-lesson-quotes';
import { LESSONS } from '../app/lessons/lessonCatalog';

/**
 * The course page's one script: picks the language (?lang=, else the browser's, else
 * Spanish, the report's own) before <oceano-view> is defined, so each figure starts in it,
 * with its alt text in that language too.
 */
type Language = 'es' | 'en';

function pageLanguage(): Language {
  const asked = new URLSearchParams(location.search).get('lang');
  if (asked === 'es' || asked === 'en') return asked;
  for (const tag of navigator.languages) {
    const primary = tag.slice(0, 2).toLowerCase();
    if (primary === 'es' || primary === 'en') return primary;
  }
  return 'es';
}

const language = pageLanguage();
document.documentElement.lang = language;
document.documentElement.dataset.language = language;
for (const figure of Array.from(document.querySelectorAll<HTMLElement>('oceano-view'))) {
  figure.setAttribute('lang', language);
  const alt = figure.dataset[language === 'es' ? 'altEs' : 'altEn'];
  if (alt) figure.setAttribute('alt', alt);
}

/**
 * Each figure's "open in the app" link goes to the lesson that starts from its preset, and
 * its caption gets that lesson's lines of code, quoted from the source when the page is
 * built (the lesson cards' quotes), so what the page shows is what runs.
 */
function linkLessons(): void {
  for (const figure of Array.from(document.querySelectorAll<HTMLElement>('figure'))) {
    const preset = figure.querySelector('oceano-view')?.getAttribute('preset');
    const lesson = LESSONS.find((l) => l.preset === preset);
    const link = figure.querySelector<HTMLAnchorElement>('a.open-in-app');
    if (!link) continue;
    const url = new URL(link.href);
    if (lesson) {
      url.searchParams.delete('preset');
      url.searchParams.set('lesson', lesson.id);
    }
    url.searchParams.set('lang', language);
    link.href = url.href;
    if (!lesson) continue;
    const quote = LESSON_QUOTES[lesson.id];
    if (!quote) continue;
    const details = document.createElement('details');
    details.className = 'code-quote';
    const summary = document.createElement('summary');
    summary.textContent = `${language === 'es' ? 'El código' : 'The code'}: ${quote.file}, ${quote.firstLine}–${quote.lastLine}`;
    const code = document.createElement('code');
    code.textContent = quote.text;
    const pre = document.createElement('pre');
    pre.appendChild(code);
    details.append(summary, pre);
    figure.querySelector('figcaption')?.appendChild(details);
  }
}
linkLessons();
