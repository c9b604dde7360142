import type { Language } from '../language/i18n';

/**
 * The course in the ideas' order, beside the report's: linear waves, then dispersion and group
 * velocity, Gerstner's waves, spectra, the FFT, filtering with distance, light, and the coast. Each stage
 * lists lessons of the catalogue (lessonCatalog.ts) by id; a lesson that teaches none of these
 * ideas (the seed's noise, the boat, culling) is left to the report's order.
 */
export interface ConceptStage {
  name: Record<Language, string>;
  lessons: readonly string[];
}

export const CONCEPT_STAGES: readonly ConceptStage[] = [
  { name: { en: 'Linear waves', es: 'Olas lineales' }, lessons: ['airy-waves'] },
  {
    name: { en: 'Dispersion and group velocity', es: 'Dispersión y velocidad de grupo' },
    lessons: ['group-velocity', 'fft-fresh-breeze', 'iwave-stone', 'iwave-compare', 'kelvin-wake'],
  },
  { name: { en: 'Gerstner’s waves', es: 'Las olas de Gerstner' }, lessons: ['gerstner-gentle', 'gerstner-steepness'] },
  { name: { en: 'Spectra', es: 'Espectros' }, lessons: ['spectra-compared', 'fft-calm', 'fft-short-fetch', 'physics-panel'] },
  { name: { en: 'The FFT', es: 'La FFT' }, lessons: ['fft-transform', 'fft-gale', 'fft-normals', 'compare-models'] },
  {
    name: { en: 'Detail with distance', es: 'El detalle con la distancia' },
    lessons: ['slope-filtering', 'lod-bands', 'lod-morph', 'horizon'],
  },
  {
    name: { en: 'Light', es: 'La luz' },
    lessons: [
      'light-units',
      'sky-cube',
      'reflection',
      'fresnel',
      'fresnel-schlick',
      'sun-glint',
      'water-colour',
      'snell-window',
      'underwater-fog',
      'caustics',
      'god-rays',
    ],
  },
  {
    name: { en: 'The coast', es: 'La costa' },
    lessons: ['coast-dispersion', 'coast-refraction', 'coast-shoaling', 'coast-breaking'],
  },
];

/** The ideas' order as one list of lesson ids. */
export const CONCEPT_PATH: readonly string[] = CONCEPT_STAGES.flatMap((stage) => stage.lessons);

/** The two orders the lessons drawer offers. */
export type LessonOrder = 'report' | 'ideas';
export const LESSON_ORDERS: readonly LessonOrder[] = ['report', 'ideas'];
export const ORDER_NAMES: Record<LessonOrder, Record<Language, string>> = {
  report: { en: 'The report’s order', es: 'El orden del informe' },
  ideas: { en: 'The ideas’ order', es: 'El orden de las ideas' },
};
