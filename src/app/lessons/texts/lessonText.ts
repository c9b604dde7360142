import type { Language } from '../../language/i18n';
import type { ReferenceKey } from '../bibliography';

/** What one lesson card says (lessonTexts.ts gathers them). */
export interface LessonText {
  text: Record<Language, string>;
  /** One or more <math> elements. */
  math: string;
  /**
   * Asked before the student touches anything; the answer waits behind a button, and the
   * live view shows it.
   */
  question: { ask: Record<Language, string>; answer: Record<Language, string> };
  /** One line where the quoted code is a stand-in or an artistic choice, not physics. */
  choice?: Record<Language, string>;
  /** The works behind the card (keys of BIBLIOGRAPHY in bibliography.ts). */
  references?: ReferenceKey[];
}
