import type { Language } from '../language/i18n';
import type { ParamKey } from '../../sim/params/params';
import { LESSONS, type Lesson } from './lessonCatalog';

/** The course's chapters: the seed report's sections in its order, then what lies beyond it (names below). */
export const LESSON_SECTIONS = [
  'surface',
  'motion',
  'noise',
  'normals',
  'envmap',
  'optics',
  'boat',
  'underwater',
  'lod',
  'culling',
  'spectral',
  'gerstner',
  'compare',
  'physics',
  'wake',
  'interactive',
  'horizon',
  'linearWaves',
  'spectra',
  'filtering',
  'light',
] as const;
export type LessonSection = (typeof LESSON_SECTIONS)[number];

/** What a lesson draws over the picture besides its card (lessonLegend.ts). */
export type LessonLegend = 'lodBands' | 'kelvinAngle' | 'snellWindow' | 'hullPoints';

/** The names of the course's chapters, and which lie beyond the seed report. */
export const SECTION_NAMES: Record<LessonSection, Record<Language, string> & { beyondSeed: boolean }> = {
  surface: { en: 'Water surface', es: 'Superficie del agua', beyondSeed: false },
  motion: { en: 'Motion', es: 'Movimiento', beyondSeed: false },
  noise: { en: 'Value noise (the report’s “Perlin”)', es: 'Ruido de valor (el “Perlin” del informe)', beyondSeed: false },
  normals: { en: 'Normals', es: 'Normales', beyondSeed: false },
  envmap: { en: 'Environment map', es: 'Environment map', beyondSeed: false },
  optics: { en: 'Optics: Snell, Fresnel', es: 'Óptica: Snell, Fresnel', beyondSeed: false },
  boat: { en: 'CPU shader and the boat', es: 'CPU shader y el barco', beyondSeed: false },
  underwater: { en: 'Under the water', es: 'Bajo el agua', beyondSeed: false },
  lod: { en: 'Optimisation: LOD', es: 'Optimización: LOD', beyondSeed: false },
  culling: { en: 'Frustum culling', es: 'Frustum culling', beyondSeed: false },
  spectral: { en: 'The spectral ocean (FFT)', es: 'El océano espectral (FFT)', beyondSeed: true },
  gerstner: { en: 'Gerstner waves', es: 'Olas de Gerstner', beyondSeed: true },
  compare: { en: 'Models side by side', es: 'Modelos lado a lado', beyondSeed: true },
  physics: { en: 'Physics against theory', es: 'Física frente a teoría', beyondSeed: true },
  wake: { en: 'The Kelvin wake', es: 'La estela de Kelvin', beyondSeed: true },
  interactive: { en: 'Interactive waves (iWave)', es: 'Olas interactivas (iWave)', beyondSeed: true },
  horizon: { en: 'The sea to the horizon', es: 'El mar hasta el horizonte', beyondSeed: true },
  linearWaves: { en: 'Ideas: linear waves and their groups', es: 'Ideas: olas lineales y sus grupos', beyondSeed: true },
  spectra: { en: 'Ideas: spectra and the FFT', es: 'Ideas: espectros y la FFT', beyondSeed: true },
  filtering: { en: 'Ideas: filtering with distance', es: 'Ideas: el filtrado con la distancia', beyondSeed: true },
  light: { en: 'Ideas: light’s units and the water’s colour', es: 'Ideas: las unidades de la luz y el color del agua', beyondSeed: true },
};

/** Where each lesson sits in the course, the one to five parameters its card offers, and its legend. */
export const LESSON_OUTLINE: Record<string, { section: LessonSection; controls: ParamKey[]; legend?: LessonLegend }> = {
  'flat-plane': { section: 'surface', controls: ['wireframe', 'lodDistance'] },
  'displaced-plane': { section: 'surface', controls: ['wireframe', 'swellAmplitude', 'rippleStrength'] },
  swell: { section: 'motion', controls: ['swellAmplitude', 'swellFrequency'] },
  'swell-maximum': { section: 'motion', controls: ['swellAmplitude', 'swellFrequency'] },
  'perlin-hash': { section: 'noise', controls: ['seed'] },
  'perlin-smoothing': { section: 'noise', controls: ['seed'] },
  'perlin-octaves': { section: 'noise', controls: ['seed'] },
  'heightmap-blend': { section: 'noise', controls: ['rippleBlendSpeed', 'seed', 'view'] },
  'normals-wrong': { section: 'normals', controls: ['normals', 'shading'] },
  'normals-right': { section: 'normals', controls: ['normals', 'shading', 'swellAmplitude'] },
  'sky-cube': { section: 'envmap', controls: ['sunElevation', 'sunAzimuth', 'view'] },
  reflection: { section: 'envmap', controls: ['sunElevation', 'sunAzimuth', 'fresnel', 'seaRoughness', 'skyBlur'] },
  fresnel: { section: 'optics', controls: ['fresnel', 'fresnelPlot'] },
  'fresnel-schlick': { section: 'optics', controls: ['fresnel', 'fresnelPlot'] },
  'sun-glint': { section: 'optics', controls: ['windSpeed', 'seaRoughness', 'sunElevation', 'exposure'] },
  'boat-twin': { section: 'boat', controls: ['swellAmplitude', 'swellFrequency', 'boatResponse'], legend: 'hullPoints' },
  'boat-pitch': { section: 'boat', controls: ['swellAmplitude', 'swellFrequency', 'boatHeading'], legend: 'hullPoints' },
  'snell-window': { section: 'underwater', controls: ['fresnel', 'blurStrength'], legend: 'snellWindow' },
  'underwater-fog': { section: 'underwater', controls: ['fogDensity', 'blurStrength', 'seaBedDepth'] },
  caustics: { section: 'underwater', controls: ['caustics', 'causticsIntensity', 'seaBedDepth'] },
  'god-rays': { section: 'underwater', controls: ['godRays', 'godRaysIntensity', 'fogDensity'] },
  'lod-bands': { section: 'lod', controls: ['lodDistance', 'lodBands', 'lodColors'], legend: 'lodBands' },
  'lod-morph': { section: 'lod', controls: ['lodMorph', 'wireframe', 'lodDistance'], legend: 'lodBands' },
  'frustum-culling': { section: 'culling', controls: ['freezeCulling', 'lodBruteForce'], legend: 'lodBands' },
  'fft-calm': { section: 'spectral', controls: ['windSpeed', 'spectrum', 'waves'] },
  'fft-fresh-breeze': { section: 'spectral', controls: ['windSpeed', 'windDirection', 'spreading', 'depth'] },
  'fft-short-fetch': { section: 'spectral', controls: ['fetch', 'windSpeed', 'spectrum'] },
  'fft-gale': { section: 'spectral', controls: ['windSpeed', 'choppiness', 'foamFade', 'waveGroups', 'windrows'] },
  'fft-normals': { section: 'spectral', controls: ['normalsCompare', 'shading'] },
  'gerstner-gentle': { section: 'gerstner', controls: ['gerstnerSteepness', 'gerstnerCount'] },
  'gerstner-steepness': { section: 'gerstner', controls: ['gerstnerSteepness', 'gerstnerCount'] },
  'compare-models': { section: 'compare', controls: ['compareSplit', 'compareSplit2', 'windSpeed'] },
  'physics-panel': { section: 'physics', controls: ['physics', 'windSpeed', 'spectrum'] },
  'kelvin-wake': { section: 'wake', controls: ['boatSpeed', 'wakeGuide', 'wakeStrength'], legend: 'kelvinAngle' },
  'wake-turn': { section: 'wake', controls: ['boatTurnRate', 'boatSpeed', 'wakeGuide'], legend: 'kelvinAngle' },
  'waves-as-simulation': { section: 'interactive', controls: ['interactiveWaves', 'waves', 'windSpeed'] },
  'iwave-stone': { section: 'interactive', controls: ['iwaveGuide', 'timeScale', 'interactiveWaves'] },
  'iwave-compare': { section: 'interactive', controls: ['iwaveEquation', 'iwaveGuide', 'timeScale'] },
  'iwave-boat': { section: 'interactive', controls: ['boatSpeed', 'wake', 'wakeStrength', 'interactiveWaves'] },
  horizon: { section: 'horizon', controls: ['lodColors', 'lodDistance', 'visibility'], legend: 'lodBands' },
  'airy-waves': { section: 'linearWaves', controls: ['gerstnerCount', 'gerstnerSteepness', 'windSpeed'] },
  'group-velocity': { section: 'linearWaves', controls: ['iwaveGuide', 'timeScale'] },
  'spectra-compared': { section: 'spectra', controls: ['spectrum', 'windSpeed', 'fetch'] },
  'fft-transform': { section: 'spectra', controls: ['seed', 'physics', 'windSpeed'] },
  'slope-filtering': { section: 'filtering', controls: ['seaRoughness', 'skyBlur', 'sunElevation', 'windSpeed'] },
  'light-units': { section: 'light', controls: ['exposure', 'sunElevation'] },
  'water-colour': { section: 'light', controls: ['subsurface', 'sunAzimuth', 'waterColorPicked'] },
};

/** A lesson with where it sits in the course, its controls and its legend. */
export type OutlinedLesson = Lesson & (typeof LESSON_OUTLINE)[string];
export const outlined = (lesson: Lesson): OutlinedLesson => ({ ...lesson, ...LESSON_OUTLINE[lesson.id] });

/** Each lesson's title, by id. */
export const LESSON_TITLES: Record<string, Record<Language, string>> = {
  'flat-plane': { en: 'A flat grid of vertices', es: 'Una malla plana de vértices' },
  'displaced-plane': { en: 'The grid displaced in the vertex shader', es: 'La malla desplazada en el vertex shader' },
  swell: { en: 'The swell: sines times cosines', es: 'El oleaje: senos por cosenos' },
  'swell-maximum': { en: 'Top “frequency” (wavenumber) and amplitude', es: 'Máxima “frecuencia” (número de onda) y amplitud' },
  'perlin-hash': { en: 'Step 1: an integer noise function (value noise)', es: 'Paso 1: una función de ruido entera (ruido de valor)' },
  'perlin-smoothing': { en: 'Step 2: smoothing with the neighbours', es: 'Paso 2: suavizado con los vecinos' },
  'perlin-octaves': { en: 'Step 3: interpolation and octaves', es: 'Paso 3: interpolación y octavas' },
  'heightmap-blend': { en: 'Two heightmaps blended in time', es: 'Dos mapas de alturas mezclados en el tiempo' },
  'normals-wrong': { en: 'Wrong normals: the flat plane’s', es: 'Normales incorrectas: las del plano' },
  'normals-right': { en: 'Right normals from fabricated neighbours', es: 'Normales correctas con vecinos fabricados' },
  'sky-cube': { en: 'The sky as a cube map', es: 'El cielo como cube map' },
  reflection: { en: 'The cube map reflected', es: 'El cube map reflejado' },
  fresnel: { en: 'Fresnel: how much the sea reflects', es: 'Fresnel: cuánto refleja el mar' },
  'fresnel-schlick': { en: 'The table against Schlick', es: 'La tabla frente a Schlick' },
  'sun-glint': { en: 'The sun’s glitter and the tone curve', es: 'El destello del sol y la curva de tono' },
  'boat-twin': { en: 'The CPU twin of the shader', es: 'El gemelo en CPU del shader' },
  'boat-pitch': { en: 'Heave, pitch and roll', es: 'Elevación, cabeceo y balanceo' },
  'snell-window': { en: 'Snell’s window', es: 'La ventana de Snell' },
  'underwater-fog': { en: 'Fog and blur under the water', es: 'Niebla y desenfoque bajo el agua' },
  caustics: { en: 'Caustics on the sea bed', es: 'Cáusticas en el fondo' },
  'god-rays': { en: 'God rays', es: 'Rayos de luz' },
  'lod-bands': { en: 'Distance bands', es: 'Bandas de distancia' },
  'lod-morph': { en: 'Geomorphing between bands', es: 'Geomorfismo entre bandas' },
  'frustum-culling': { en: 'The quadtree and the frozen frustum', es: 'El quadtree y el frustum congelado' },
  'fft-calm': { en: 'A wind spectrum: a gentle breeze', es: 'Un espectro de viento: brisa débil' },
  'fft-fresh-breeze': { en: 'Dispersion: a fresh breeze', es: 'Dispersión: brisa fresca' },
  'fft-short-fetch': { en: 'JONSWAP: a young sea', es: 'JONSWAP: un mar joven' },
  'fft-gale': { en: 'Choppiness and foam from the Jacobian', es: 'Crestas y espuma desde el jacobiano' },
  'fft-normals': { en: 'Exact normals from the spectrum', es: 'Normales exactas desde el espectro' },
  'gerstner-gentle': { en: 'Trochoids: Gerstner’s waves', es: 'Trocoides: las olas de Gerstner' },
  'gerstner-steepness': { en: 'Steepness and the limit Σ QkA ≤ 1', es: 'Pendiente y el límite Σ QkA ≤ 1' },
  'compare-models': { en: 'Three models, one sea', es: 'Tres modelos, un mar' },
  'physics-panel': { en: 'The sea measured against theory', es: 'El mar medido frente a la teoría' },
  'kelvin-wake': { en: 'Kelvin’s 19.47°', es: 'Los 19,47° de Kelvin' },
  'wake-turn': { en: 'A wake along a turn', es: 'Una estela en una curva' },
  'waves-as-simulation': { en: 'Waves as a simulation', es: 'Las olas como simulación' },
  'iwave-stone': { en: 'A stone: long waves lead', es: 'Una piedra: las olas largas van delante' },
  'iwave-compare': { en: 'Dispersion against the wave equation', es: 'Dispersión frente a la ecuación de ondas' },
  'iwave-boat': { en: 'The boat pushes water', es: 'El barco empuja el agua' },
  horizon: { en: 'Rings out to the horizon', es: 'Anillos hasta el horizonte' },
  'airy-waves': { en: 'Linear (Airy) waves: orbits and energy', es: 'Olas lineales (Airy): órbitas y energía' },
  'group-velocity': { en: 'Phase speed and group velocity', es: 'Velocidad de fase y velocidad de grupo' },
  'spectra-compared': { en: 'Phillips beside Pierson–Moskowitz and JONSWAP', es: 'Phillips junto a Pierson–Moskowitz y JONSWAP' },
  'fft-transform': {
    en: 'The FFT itself: random amplitudes, butterflies, tiles',
    es: 'La FFT en sí: amplitudes aleatorias, mariposas, teselas',
  },
  'slope-filtering': {
    en: 'Filtering: slopes too fine to draw become roughness',
    es: 'Filtrado: las pendientes demasiado finas se vuelven rugosidad',
  },
  'light-units': {
    en: 'Light’s units: HDR radiance, the tone curve, sRGB',
    es: 'Las unidades de la luz: radiancia HDR, curva de tono, sRGB',
  },
  'water-colour': { en: 'The water’s colour and the crests’ glow', es: 'El color del agua y el brillo de las crestas' },
};

/** The lessons whose card has a measurement exercise (src/sim/teaching/measurementExercises.ts; a unit test keeps the two alike). */
export const EXERCISE_LESSONS: readonly string[] = [
  'fft-calm',
  'fft-fresh-breeze',
  'fft-short-fetch',
  'fft-gale',
  'physics-panel',
  'kelvin-wake',
  'airy-waves',
  'gerstner-gentle',
  'spectra-compared',
  'sun-glint',
  'fft-transform',
  'wake-turn',
  'iwave-compare',
  'iwave-stone',
  'group-velocity',
];

/** `[{ id, title, section, question, exercise }]` in a language, in the course's order (oceano.lessons()). */
export function lessonList(language: Language): { id: string; title: string; section: string; question: boolean; exercise: boolean }[] {
  return LESSONS.map((lesson) => ({
    id: lesson.id,
    title: LESSON_TITLES[lesson.id][language],
    section: SECTION_NAMES[LESSON_OUTLINE[lesson.id].section][language],
    // Every card asks its question before anything else: LessonText requires one (lessonTexts.ts).
    question: true,
    exercise: EXERCISE_LESSONS.includes(lesson.id),
  }));
}
