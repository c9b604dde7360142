import './course.css';

/**
 * The course page's one script: picks the language (?lang=, else the browser's, else
 * Spanish, the report's own) before <oceano-view> is defined, so each figure starts in it,
 * with its alt text and its "open in the app" link in that language too.
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
for (const link of Array.from(document.querySelectorAll<HTMLAnchorElement>('a.open-in-app'))) {
  const url = new URL(link.href);
  url.searchParams.set('lang', language);
  link.href = url.href;
}
