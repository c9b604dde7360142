import type { Language, Translator } from './i18n';

/**
 * The words of the teaching tools (the lessons drawer, its legends, the panel's notes on
 * parameters a model does not read, the time controls), beside i18n.ts's: only the chunks
 * fetched after the first frame use them, so they travel there and not in the page's first script.
 */
export type TeachingWordId =
  | 'lessonsTitle'
  | 'lessonsCollapse'
  | 'lessonsExpand'
  | 'lessonsList'
  | 'lessonNext'
  | 'lessonPrevious'
  | 'lessonCode'
  | 'lessonControls'
  | 'lessonLegend'
  | 'lessonPosition'
  | 'lodBandLegend'
  | 'kelvinAngleLabel'
  | 'snellWindowLabel'
  | 'unusedBySeed'
  | 'unusedBySpectral'
  | 'unusedByNonFft'
  | 'unusedByNonGerstner'
  | 'timeScale'
  | 'step'
  | 'coursePage';

const WORDS: Record<Language, Record<TeachingWordId, string>> = {
  en: {
    lessonsTitle: 'Lessons',
    lessonsCollapse: 'Hide the lessons',
    lessonsExpand: 'Show the lessons',
    lessonsList: 'All lessons',
    lessonNext: 'Next lesson',
    lessonPrevious: 'Previous lesson',
    lessonCode: 'The code that does it',
    lessonControls: 'Try it',
    lessonLegend: 'Legend',
    lessonPosition: 'Lesson {n} of {total}',
    lodBandLegend: 'Band {band}: from {from} m',
    kelvinAngleLabel: '19.47° (Kelvin)',
    snellWindowLabel: "48.6°: edge of Snell's window",
    unusedBySeed: 'not read by the seed waves (only by fft and gerstner)',
    unusedBySpectral: 'read only by the seed waves',
    unusedByNonFft: 'read only by the fft waves',
    unusedByNonGerstner: 'read only by the gerstner waves',
    timeScale: 'Speed',
    step: 'Step one frame (1/60 s)',
    coursePage: 'The course page: the seed report, live, every figure in one chapter',
  },
  es: {
    lessonsTitle: 'Lecciones',
    lessonsCollapse: 'Ocultar las lecciones',
    lessonsExpand: 'Mostrar las lecciones',
    lessonsList: 'Todas las lecciones',
    lessonNext: 'Lección siguiente',
    lessonPrevious: 'Lección anterior',
    lessonCode: 'El código que lo hace',
    lessonControls: 'Pruébalo',
    lessonLegend: 'Leyenda',
    lessonPosition: 'Lección {n} de {total}',
    lodBandLegend: 'Banda {band}: desde {from} m',
    kelvinAngleLabel: '19,47° (Kelvin)',
    snellWindowLabel: '48,6°: borde de la ventana de Snell',
    unusedBySeed: 'las olas semilla no lo leen (solo fft y gerstner)',
    unusedBySpectral: 'solo lo leen las olas semilla',
    unusedByNonFft: 'solo lo leen las olas fft',
    unusedByNonGerstner: 'solo lo leen las olas gerstner',
    timeScale: 'Velocidad',
    step: 'Avanzar un fotograma (1/60 s)',
    coursePage: 'La página del curso: el informe semilla, en vivo, con todas sus figuras en un capítulo',
  },
};

/** A teaching word in the translator's language. */
export function teachingWord(tr: Pick<Translator, 'language'>, id: TeachingWordId): string {
  return WORDS[tr.language][id];
}
