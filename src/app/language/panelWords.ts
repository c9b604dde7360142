import type { Language, Translator } from './i18n';

/**
 * The control panel's own words (its title, folders, buttons and counters), es/en. Only the
 * panel's chunk, fetched after the first frame (AppControls.loadPanel), reads them, so they
 * travel with it and not in the page's first script.
 */
export type PanelWordId =
  | 'panelTitle'
  | 'folderSwell'
  | 'folderSpectral'
  | 'folderRipples'
  | 'folderLight'
  | 'folderView'
  | 'folderBoat'
  | 'folderLod'
  | 'folderUnderwater'
  | 'folderGerstner'
  | 'folderPhysics'
  | 'folderCoast'
  | 'folderCompare'
  | 'dive'
  | 'surface'
  | 'folderLiveCounts'
  | 'countChunks'
  | 'countTriangles'
  | 'countDrawCalls'
  | 'countPerBand'
  | 'froudeNumber'
  | 'playing'
  | 'share';

const WORDS: Record<Language, Record<PanelWordId, string>> = {
  en: {
    panelTitle: 'Oceano',
    folderSwell: 'Swell',
    folderCoast: 'Coast',
    folderSpectral: 'Wind & spectrum (fft, gerstner)',
    folderRipples: 'Ripples (Perlin)',
    folderLight: 'Light & water',
    folderView: 'View',
    folderBoat: 'Boat',
    folderLod: 'LOD & culling',
    folderUnderwater: 'Underwater',
    folderGerstner: 'Gerstner waves',
    folderPhysics: 'Physics vs theory',
    folderCompare: 'Models side by side',
    dive: 'Dive under the surface',
    surface: 'Back to the surface view',
    folderLiveCounts: 'LOD counts (live)',
    countChunks: 'Chunks visible / total',
    countTriangles: 'Triangles',
    countDrawCalls: 'Draw calls',
    countPerBand: 'Chunks per band',
    froudeNumber: 'Froude number U/√(gL)',
    playing: 'Play',
    share: 'Share link',
  },
  es: {
    panelTitle: 'Oceano',
    folderSwell: 'Oleaje',
    folderCoast: 'Costa',
    folderSpectral: 'Viento y espectro (fft, gerstner)',
    folderRipples: 'Ondas (Perlin)',
    folderLight: 'Luz y agua',
    folderView: 'Vista',
    folderBoat: 'Barco',
    folderLod: 'LOD y recorte',
    folderUnderwater: 'Bajo el agua',
    folderGerstner: 'Ondas de Gerstner',
    folderPhysics: 'Física frente a teoría',
    folderCompare: 'Modelos lado a lado',
    dive: 'Sumergirse',
    surface: 'Volver a la superficie',
    folderLiveCounts: 'Contadores de LOD (en vivo)',
    countChunks: 'Parcelas visibles / total',
    countTriangles: 'Triángulos',
    countDrawCalls: 'Llamadas de dibujo',
    countPerBand: 'Parcelas por banda',
    froudeNumber: 'Número de Froude U/√(gL)',
    playing: 'Reproducir',
    share: 'Compartir enlace',
  },
};

/** A panel word in the translator's language. */
export function panelWord(tr: Pick<Translator, 'language'>, id: PanelWordId): string {
  return WORDS[tr.language][id];
}
