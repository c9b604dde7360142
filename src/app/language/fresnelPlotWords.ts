import type { Language } from './i18n';

/**
 * The words of the Fresnel plot, es/en. Only the plot's chunk, fetched when the plot is first
 * shown, reads them, so they stay out of the page's first script.
 */
export const FRESNEL_PLOT_WORDS: Record<Language, Record<'label' | 'title' | 'axis' | 'exact' | 'schlick', string>> = {
  en: {
    label: 'Plot of the Fresnel reflectance of water against the angle of incidence, exact and Schlick',
    title: 'Fresnel reflectance, air → water',
    axis: 'angle of incidence',
    exact: 'exact (table uploaded to the GPU)',
    schlick: 'Schlick’s approximation',
  },
  es: {
    label: 'Gráfico de la reflectancia de Fresnel del agua según el ángulo de incidencia, exacta y de Schlick',
    title: 'Reflectancia de Fresnel, aire → agua',
    axis: 'ángulo de incidencia',
    exact: 'exacta (tabla subida a la GPU)',
    schlick: 'aproximación de Schlick',
  },
};
