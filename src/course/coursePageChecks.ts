import { findLesson, lessonView } from '../app/lessons/lessonCatalog';
import { parseSettings } from '../app/url/urlState';
import { paramKeys } from '../sim/params/params';

/** HTML lowercases attribute names: the parameter each lowercase name stands for, as <oceano-view> reads it. */
const PARAM_BY_LOWERCASE = new Map(paramKeys.map((key) => [key.toLowerCase(), key]));

/**
 * What the course page's tests hold it to, as pure functions of what the page shows: each
 * lesson once, each figure showing its own lesson (view, words, code), one Spanish register.
 */

/** The other register's words (COMMON glossary: malla, barco, balanceo, controles). */
export const BANNED_SPANISH = ['grilla', 'grillas', 'bote', 'botes', 'rolido', 'perilla', 'perillas'] as const;

/**
 * The banned words a Spanish text uses, each once, as found. Words inside quotation marks
 * (“…”, «…») are left alone: they cite the report's own titles (“Quiero mover el bote”).
 */
export function bannedSpanishWords(text: string): string[] {
  const own = text.replace(/“[^”]*”|«[^»]*»/g, ' ');
  const found = own.toLowerCase().match(new RegExp(`(?<![\\p{L}])(${BANNED_SPANISH.join('|')})(?![\\p{L}])`, 'gu')) ?? [];
  return [...new Set(found)];
}

/** The lessons a course page names (data-lesson), in page order. */
export function pageLessonIds(html: string): string[] {
  return Array.from(html.matchAll(/data-lesson="([^"]*)"/g), (m) => m[1]);
}

/** What a figure or card shows, read off the page. */
export interface ShownLesson {
  lesson: string;
  /** The caption's words. */
  text: string;
  /** The quoted code, null when none is shown. */
  code: string | null;
  /** A live figure's <oceano-view> attributes; null for a card. */
  attributes: [string, string][] | null;
}

/** What a lesson's card says in the page's language, and the code it quotes. */
export interface CardSource {
  text: (id: string) => string;
  code: (id: string) => string | null;
}

/** Each way a shown lesson differs from its own card and view, in words; empty when it is its own. */
export function shownLessonFaults(shown: ShownLesson, card: CardSource): string[] {
  const faults: string[] = [];
  const lesson = findLesson(shown.lesson);
  if (!lesson) return [`${shown.lesson}: no such lesson`];
  if (shown.text !== card.text(lesson.id)) faults.push(`${lesson.id}: the caption's text is not the card's`);
  if (shown.code !== card.code(lesson.id)) faults.push(`${lesson.id}: the quoted code is not the lesson's`);
  if (shown.attributes) {
    const state = parseSettings(shown.attributes.map(([name, value]): [string, string] => [PARAM_BY_LOWERCASE.get(name.toLowerCase()) ?? name, value]));
    const view = lessonView(lesson);
    if (JSON.stringify(state.params) !== JSON.stringify(view.params)) faults.push(`${lesson.id}: the figure's parameters are not the lesson's`);
    if (JSON.stringify(state.camera) !== JSON.stringify(view.camera)) faults.push(`${lesson.id}: the figure's camera is not the lesson's`);
    if (state.notices.length) faults.push(`${lesson.id}: the figure's attributes raise notices`);
  }
  return faults;
}
