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
  | 'hullPointsLegend'
  | 'hull_centre'
  | 'hull_bow'
  | 'hull_stern'
  | 'hull_port'
  | 'hull_starboard'
  | 'picture_heightmap0'
  | 'picture_heightmap1'
  | 'picture_cascade0'
  | 'picture_cascade1'
  | 'picture_hash'
  | 'picture_smoothed'
  | 'picture_interpolated'
  | 'picture_octaves'
  | 'picture_first'
  | 'picture_blend'
  | 'picture_second'
  | 'skyCubeCaption'
  | 'face_px'
  | 'face_nx'
  | 'face_py'
  | 'face_ny'
  | 'face_pz'
  | 'face_nz'
  | 'unusedBySeed'
  | 'unusedBySpectral'
  | 'unusedByNonFft'
  | 'unusedByNonGerstner'
  | 'unusedWithoutFoam'
  | 'unusedWithoutRoughness'
  | 'unusedWithoutPickedColor'
  | 'unusedWithoutCaustics'
  | 'unusedWithoutGodRays'
  | 'timeScale'
  | 'step'
  | 'seaTools'
  | 'dropStone'
  | 'coursePage'
  | 'lessonQuestion'
  | 'showAnswer'
  | 'hideAnswer'
  | 'lessonChoice'
  | 'lessonReferences'
  | 'bibliography'
  | 'glossary'
  | 'backToLessons'
  | 'glossaryTermHint';

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
    hullPointsLegend:
      'The dots: the five points where the hull asks the CPU twin for the water’s height (centre, bow and stern, port and starboard).',
    hull_centre: 'centre',
    hull_bow: 'bow',
    hull_stern: 'stern',
    hull_port: 'port',
    hull_starboard: 'starboard',
    picture_heightmap0: 'Heightmap H₀, as the vertex shader samples it',
    picture_heightmap1: 'Heightmap H₁, as the vertex shader samples it',
    picture_cascade0: 'Largest FFT cascade: its height field',
    picture_cascade1: 'Smallest FFT cascade: its height field',
    picture_hash: '1 · Integer noise n(i, j) on a 16 × 16 lattice',
    picture_smoothed: '2 · Smoothed with its 3 × 3 neighbours',
    picture_interpolated: '3 · That lattice cosine-interpolated: one octave',
    picture_octaves: '4 · Five octaves summed: heightmap H₀',
    picture_first: 'Heightmap H₀',
    picture_blend: '(1 − b) H₀ + b H₁, now b = {b}',
    picture_second: 'Heightmap H₁',
    skyCubeCaption: 'The sky’s cube map unfolded, seen from inside the cube',
    face_px: '+x',
    face_nx: '−x',
    face_py: '+y (up)',
    face_ny: '−y (down)',
    face_pz: '+z (behind)',
    face_nz: '−z (ahead)',
    unusedBySeed: 'not read by the seed waves (only by fft and gerstner)',
    unusedBySpectral: 'read only by the seed waves',
    unusedByNonFft: 'read only by the fft waves',
    unusedByNonGerstner: 'read only by the gerstner waves',
    unusedWithoutFoam: 'read only while Foam is on',
    unusedWithoutRoughness: 'read only while Roughness (Cox & Munk) is on: a mirror has nothing to blur',
    unusedWithoutPickedColor: 'read only while Use the picked water colour is on: the colour comes from optics',
    unusedWithoutCaustics: 'read only while Caustics is on',
    unusedWithoutGodRays: 'read only while God rays is on',
    timeScale: 'Speed',
    step: 'Step one frame (1/60 s)',
    seaTools: 'Sea tools: probe, ruler, stones',
    dropStone: 'Drop a stone (interactive waves)',
    coursePage: 'The course page: the seed report, live, every figure in one chapter',
    lessonQuestion: 'Before you touch anything',
    showAnswer: 'Show the answer',
    hideAnswer: 'Hide the answer',
    lessonChoice: 'A choice, not physics:',
    lessonReferences: 'References',
    bibliography: 'Bibliography',
    glossary: 'Glossary',
    backToLessons: 'Back to the lessons',
    glossaryTermHint: '{term}: what it means',
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
    hullPointsLegend:
      'Los puntos: los cinco lugares donde el casco pide al gemelo en CPU la altura del agua (centro, proa y popa, babor y estribor).',
    hull_centre: 'centro',
    hull_bow: 'proa',
    hull_stern: 'popa',
    hull_port: 'babor',
    hull_starboard: 'estribor',
    picture_heightmap0: 'Mapa de alturas H₀, tal como lo lee el vertex shader',
    picture_heightmap1: 'Mapa de alturas H₁, tal como lo lee el vertex shader',
    picture_cascade0: 'Cascada FFT mayor: su campo de alturas',
    picture_cascade1: 'Cascada FFT menor: su campo de alturas',
    picture_hash: '1 · Ruido entero n(i, j) en una red de 16 × 16',
    picture_smoothed: '2 · Suavizado con sus 3 × 3 vecinos',
    picture_interpolated: '3 · Esa red interpolada con cosenos: una octava',
    picture_octaves: '4 · Cinco octavas sumadas: mapa de alturas H₀',
    picture_first: 'Mapa de alturas H₀',
    picture_blend: '(1 − b) H₀ + b H₁, ahora b = {b}',
    picture_second: 'Mapa de alturas H₁',
    skyCubeCaption: 'El cube map del cielo desplegado, visto desde dentro del cubo',
    face_px: '+x',
    face_nx: '−x',
    face_py: '+y (arriba)',
    face_ny: '−y (abajo)',
    face_pz: '+z (detrás)',
    face_nz: '−z (de frente)',
    unusedBySeed: 'las olas semilla no lo leen (solo fft y gerstner)',
    unusedBySpectral: 'solo lo leen las olas semilla',
    unusedByNonFft: 'solo lo leen las olas fft',
    unusedByNonGerstner: 'solo lo leen las olas gerstner',
    unusedWithoutFoam: 'solo se lee con Espuma activada',
    unusedWithoutRoughness: 'solo se lee con Rugosidad (Cox y Munk) activada: un espejo no tiene nada que difuminar',
    unusedWithoutPickedColor: 'solo se lee con Usar el color de agua elegido activado: el color sale de la óptica',
    unusedWithoutCaustics: 'solo se lee con Cáusticas activadas',
    unusedWithoutGodRays: 'solo se lee con Rayos de luz activados',
    timeScale: 'Velocidad',
    step: 'Avanzar un fotograma (1/60 s)',
    seaTools: 'Herramientas: sonda, regla, piedras',
    dropStone: 'Tirar una piedra (olas interactivas)',
    coursePage: 'La página del curso: el informe semilla, en vivo, con todas sus figuras en un capítulo',
    lessonQuestion: 'Antes de tocar nada',
    showAnswer: 'Mostrar la respuesta',
    hideAnswer: 'Ocultar la respuesta',
    lessonChoice: 'Una elección, no física:',
    lessonReferences: 'Referencias',
    bibliography: 'Bibliografía',
    glossary: 'Glosario',
    backToLessons: 'Volver a las lecciones',
    glossaryTermHint: '{term}: qué significa',
  },
};

/** A teaching word in the translator's language. */
export function teachingWord(tr: Pick<Translator, 'language'>, id: TeachingWordId): string {
  return WORDS[tr.language][id];
}
