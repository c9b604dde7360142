import './course.css';
import { findLesson } from '../app/lessons/lessonCatalog';
import { LESSON_TITLES } from '../app/lessons/lessonOutline';
import { lessonPoster, lessonViewAttributes } from './lessonFigure';

/**
 * The course page's first script: picks the language (?lang=, else the browser's, else
 * Spanish, the report's own) and gives each figure its lesson's view, poster and alt text,
 * all before <oceano-view> is defined, so each figure starts as its lesson in that language.
 * Each figure and card names its lesson (data-lesson); its caption is that lesson's card,
 * fetched after this script (courseCaptions.ts), so the page cannot drift from the cards.
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
for (const figure of Array.from(document.querySelectorAll<HTMLElement>('figure[data-lesson]'))) {
  const id = figure.dataset.lesson!;
  const lesson = findLesson(id);
  const view = figure.querySelector('oceano-view');
  if (!lesson || !view) throw new Error(`The course page's figure names no lesson of the catalog: "${id}".`);
  for (const [name, value] of lessonViewAttributes(lesson)) view.setAttribute(name, value);
  view.setAttribute('lang', language);
  view.setAttribute('poster', lessonPoster(id));
  view.setAttribute('alt', LESSON_TITLES[id][language]);
}

void import('./courseCaptions').then(({ writeCaptions }) => writeCaptions(language));
