import * as lessons from '../app/lessons/lessonCatalog';
import { findLesson, lessonView } from '../app/lessons/lessonCatalog';
import { parseSettings } from '../app/url/urlState';
import { paramKeys } from '../sim/params/params';
import type { Language } from '../app/language/i18n';
import { BIBLIOGRAPHY, type ReferenceKey } from '../app/lessons/bibliography';
import { GLOSSARY, type GlossaryKey } from '../app/lessons/glossary';
import { citation } from '../app/lessons/referenceLists';
import { workAnchor } from './backMatter';

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
  /** The citations in the caption's References fold, in order; empty when it has none. */
  references: string[];
  /** A live figure's <oceano-view> attributes; null for a card. */
  attributes: [string, string][] | null;
}

/** What a lesson's card says in the page's language, and the code it quotes. */
export interface CardSource {
  text: (id: string) => string;
  code: (id: string) => string | null;
  /** The card's references, each in full (citation form). */
  references: (id: string) => string[];
}

/** Each way a shown lesson differs from its own card and view, in words; empty when it is its own. */
export function shownLessonFaults(shown: ShownLesson, card: CardSource): string[] {
  const faults: string[] = [];
  const lesson = findLesson(shown.lesson);
  if (!lesson) return [`${shown.lesson}: no such lesson`];
  if (shown.text !== card.text(lesson.id)) faults.push(`${lesson.id}: the caption's text is not the card's`);
  if (shown.code !== card.code(lesson.id)) faults.push(`${lesson.id}: the quoted code is not the lesson's`);
  if (JSON.stringify(shown.references) !== JSON.stringify(card.references(lesson.id))) faults.push(`${lesson.id}: the caption's references are not the card's`);
  if (shown.attributes) {
    const state = parseSettings(shown.attributes.map(([name, value]): [string, string] => [PARAM_BY_LOWERCASE.get(name.toLowerCase()) ?? name, value]), lessons);
    const view = lessonView(lesson);
    if (JSON.stringify(state.params) !== JSON.stringify(view.params)) faults.push(`${lesson.id}: the figure's parameters are not the lesson's`);
    if (JSON.stringify(state.camera) !== JSON.stringify(view.camera)) faults.push(`${lesson.id}: the figure's camera is not the lesson's`);
    if (state.notices.length) faults.push(`${lesson.id}: the figure's attributes raise notices`);
  }
  return faults;
}

/** An entry of the page's bibliography or glossary: its id and its words. */
export interface ListedEntry {
  id: string;
  text: string;
}

/**
 * How the page's bibliography differs from the works the cards cite: a cited work missing
 * or not in full under its id, an entry no card cites, an id listed twice.
 */
export function bibliographyFaults(entries: ListedEntry[], cited: readonly ReferenceKey[]): string[] {
  const faults: string[] = [];
  const byId = new Map(entries.map((entry) => [entry.id, entry.text]));
  if (byId.size !== entries.length) faults.push('an id is listed twice');
  for (const key of cited) {
    const text = byId.get(workAnchor(key));
    if (text === undefined) faults.push(`${key}: cited but not in the bibliography`);
    else if (text !== citation(BIBLIOGRAPHY[key])) faults.push(`${key}: its entry is not its citation`);
  }
  const citedIds = new Set(cited.map(workAnchor));
  for (const entry of entries) if (!citedIds.has(entry.id)) faults.push(`${entry.id}: listed but cited by no card`);
  return faults;
}

/** The links (href "#id") whose target is none of `ids`. */
export function unresolvedLinks(hrefs: readonly string[], ids: readonly string[]): string[] {
  const present = new Set(ids);
  return hrefs.filter((href) => !href.startsWith('#') || !present.has(href.slice(1)));
}

/**
 * How a caption's term links go wrong: a link to no glossary entry of the page, or whose
 * words are none of that term's forms in the page's language.
 */
export function termLinkFaults(links: readonly { href: string; text: string }[], entryIds: readonly string[], language: Language): string[] {
  const faults = unresolvedLinks(links.map((link) => link.href), entryIds).map((href) => `${href}: no glossary entry`);
  for (const { href, text } of links) {
    const key = href.replace(/^#term-/, '') as GlossaryKey;
    const forms = GLOSSARY[key]?.words[language].map((form) => form.toLocaleLowerCase(language)) ?? [];
    if (!forms.includes(text.toLocaleLowerCase(language))) faults.push(`${href}: "${text}" is not that term`);
  }
  return faults;
}
