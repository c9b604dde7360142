import type { LessonText } from './texts/lessonText';
import { seedSeaTexts } from './texts/seedSeaTexts';
import { lightTexts } from './texts/lightTexts';
import { spectralSeaTexts } from './texts/spectralSeaTexts';
import { beyondTexts } from './texts/beyondTexts';
import { ideasTexts } from './texts/ideasTexts';
import { coastTexts } from './texts/coastTexts';

export type { LessonText };

/**
 * What each lesson card says: what you see and why, in our own words (40 to 120 words in
 * each language), and its key equations as MathML, which browsers draw without a library.
 * A chunk of its own, fetched with the lessons drawer after the first frame. Every card, by
 * lesson id; each part of the course in a file of its own (texts/).
 */
export const LESSON_TEXTS: Record<string, LessonText> = {
  ...seedSeaTexts,
  ...lightTexts,
  ...spectralSeaTexts,
  ...beyondTexts,
  ...ideasTexts,
  ...coastTexts,
};
