import { paramDefs, type OceanParams, type ParamKey } from '../../sim/params/params';
import type { Message, MessageId, MessageValues } from '../../sim/params/message';

export const LANGUAGES = ['en', 'es'] as const;
export type Language = (typeof LANGUAGES)[number];

export function isLanguage(text: string): text is Language {
  return (LANGUAGES as readonly string[]).includes(text);
}

/** The language we speak for a BCP 47 tag (es-ES, es_MX, EN), by its primary subtag; null if none. */
export function languageFromTag(tag: string): Language | null {
  const primary = tag.trim().toLowerCase().split(/[-_]/)[0];
  return isLanguage(primary) ? primary : null;
}

/** The first of the browser's preferred languages that we speak, else English. */
export function preferredLanguage(browserLanguages: readonly string[]): Language {
  for (const tag of browserLanguages) {
    const language = languageFromTag(tag);
    if (language) return language;
  }
  return 'en';
}

type Render = (v: MessageValues) => string;
/** Inner text ended with exactly one full stop, so "…404)." never becomes "…404).)" or "..". */
const sentence = (text: string | number | boolean | undefined) => `${String(text ?? '').trim().replace(/[.\s]+$/, '')}.`;
const unit = (v: MessageValues) => (v.unit ? ` ${v.unit}` : '');

const MESSAGES: Record<Language, Record<MessageId, Render>> = {
  en: {
    paramNotBoolean: (v) => `"${v.key}=${v.text}" is not true/false; using ${v.fallback}.`,
    paramNotColour: (v) => `"${v.key}=${v.text}" is not a colour like 0a2e45; using ${v.fallback}.`,
    paramNotChoice: (v) => `"${v.key}=${v.text}" is not one of ${v.options}; using ${v.fallback}.`,
    paramNotInteger: (v) => `"${v.key}=${v.text}" is not an integer; using the default ${v.fallback}.`,
    paramNotNumber: (v) => `"${v.key}=${v.text}" is not a number; using the default ${v.fallback}.`,
    paramClamped: (v) => `"${v.key}=${v.text}" is outside [${v.min}, ${v.max}]${unit(v)}; clamped to ${v.clamped}.`,
    timeInvalid: (v) => `"t=${v.text}" is not a time in seconds between 0 and 1e9; the animation runs from 0 instead.`,
    skyInvalid: (v) => `"sky=${v.text}" is not a path on this site; using the built-in sky.`,
    cameraInvalid: (v) => `"cam=${v.text}" is not six finite numbers x,y,z,tx,ty,tz (target apart from the position, each within ±1e6 m); using the default camera.`,
    languageInvalid: (v) => `"lang=${v.text}" is not a language we speak (en, es); using the browser's language.`,
    embedInvalid: (v) => `"embed=${v.text}" is not 1 or 0; showing the full page.`,
    presetUnknown: (v) => `There is no preset "${v.name}"; showing the default view. Presets: ${v.known}.`,
    lessonUnknown: (v) => `There is no lesson "${v.name}"; nothing was changed. Lessons: ${v.known}.`,
    unknownUrlParam: (v) => `Unknown URL parameter "${v.key}" was ignored.`,
    skyLoadFailed: (v) => `The sky images under "${v.base}" could not be loaded. Showing the sky painted from the sun instead.`,
    skyCustomSunFixed: (v) => `Showing the sky images under "${v.base}": their sun is painted in, so the sun's direction now moves only the lighting and the glint on the water.`,
    contextLost: () => 'The graphics context was lost: the GPU was reset, or this page holds more 3D views than the browser keeps alive (about 16). The ocean comes back if the browser restores the context; if it does not, reload the page.',
    shareCopied: () => 'Link to this view copied to the clipboard.',
    shareFallback: (v) => `Copy this link to share the view: ${v.url}`,
    webgl2Missing: () => 'Oceano needs WebGL2, which this browser or device does not provide. Try a recent Chrome, Firefox or Safari, or enable hardware acceleration.',
    startFailed: (v) => `Oceano could not start: ${sentence(v.error)}`,
    boatPathInvalid: (v) => `"boat=${v.text}" is not a path on this site; using the built-in boat.`,
    boatLoadFailed: (v) => `The boat could not be loaded: ${sentence(v.reason)} The ocean runs without the boat.`,
    boatUnreachable: (v) => `The boat model "${v.url}" could not be fetched. The ocean runs without the boat.`,
    boatNotFound: (v) => `The boat model "${v.url}" was not found (HTTP ${v.status}). The ocean runs without the boat.`,
    boatWebPage: (v) => `The boat model "${v.url}" is missing: the server sent a web page in its place. The ocean runs without the boat.`,
    boatNotGltf: (v) => `The boat model "${v.url}" is not a valid glTF model: neither a binary .glb nor a JSON .gltf file that three.js can read. The ocean runs without the boat.`,
    boatNoGeometry: (v) => `The boat model "${v.url}" has no geometry to float. The ocean runs without the boat.`,
    boatStateInvalid: (v) => `"boatState=${v.text}" is not ten finite numbers within the boat's area; the boat starts afresh.`,
    wakeTrackInvalid: (v) => `"wakeTrack=${v.text}" is not a recorded track; the wake is replayed from the boat's present course.`,
    modelLoadFailed: (v) => `The code of the "${v.name}" waves could not be downloaded; still showing "${v.fallback}". Choose it again later, or reload the page.`,
    underwaterLoadFailed: () => 'The underwater effects (water fog, light shafts, blur) could not be downloaded; the sea is drawn from below without them. Reload the page to try again.',
    elementAttributeInvalid: (v) => `"${v.name}=${v.text}" is not one of ${v.allowed}; using "${v.fallback}".`,
    panelLoadFailed: () => 'The control panel could not be downloaded; the ocean runs without it. Reload the page to try again.',
  },
  es: {
    paramNotBoolean: (v) => `"${v.key}=${v.text}" no es verdadero/falso; se usa ${v.fallback}.`,
    paramNotColour: (v) => `"${v.key}=${v.text}" no es un color como 0a2e45; se usa ${v.fallback}.`,
    paramNotChoice: (v) => `"${v.key}=${v.text}" no es ninguna de estas opciones: ${v.options}; se usa ${v.fallback}.`,
    paramNotInteger: (v) => `"${v.key}=${v.text}" no es un número entero; se usa el valor por defecto ${v.fallback}.`,
    paramNotNumber: (v) => `"${v.key}=${v.text}" no es un número; se usa el valor por defecto ${v.fallback}.`,
    paramClamped: (v) => `"${v.key}=${v.text}" está fuera de [${v.min}, ${v.max}]${unit(v)}; se limita a ${v.clamped}.`,
    timeInvalid: (v) => `"t=${v.text}" no es un tiempo en segundos entre 0 y 1e9; la animación corre desde 0.`,
    skyInvalid: (v) => `"sky=${v.text}" no es una ruta de este sitio; se usa el cielo incluido.`,
    cameraInvalid: (v) => `"cam=${v.text}" no son seis números finitos x,y,z,tx,ty,tz (objetivo distinto de la posición, cada uno dentro de ±1e6 m); se usa la cámara por defecto.`,
    languageInvalid: (v) => `"lang=${v.text}" no es un idioma disponible (en, es); se usa el idioma del navegador.`,
    embedInvalid: (v) => `"embed=${v.text}" no es 1 ni 0; se muestra la página completa.`,
    presetUnknown: (v) => `No existe la vista predefinida "${v.name}"; se muestra la vista por defecto. Disponibles: ${v.known}.`,
    lessonUnknown: (v) => `No existe la lección "${v.name}"; no se ha cambiado nada. Lecciones: ${v.known}.`,
    unknownUrlParam: (v) => `Se ignoró el parámetro de URL desconocido "${v.key}".`,
    skyLoadFailed: (v) => `No se pudieron cargar las imágenes del cielo en "${v.base}". Se muestra el cielo pintado a partir del sol.`,
    skyCustomSunFixed: (v) => `Se muestran las imágenes del cielo en "${v.base}": su sol está pintado en ellas, así que la dirección del sol solo mueve la iluminación y el brillo en el agua.`,
    contextLost: () => 'Se perdió el contexto gráfico: la GPU se reinició, o esta página tiene más vistas 3D de las que el navegador mantiene (unas 16). El océano vuelve si el navegador restablece el contexto; si no, recarga la página.',
    shareCopied: () => 'Enlace a esta vista copiado al portapapeles.',
    shareFallback: (v) => `Copia este enlace para compartir la vista: ${v.url}`,
    webgl2Missing: () => 'Oceano necesita WebGL2, que este navegador o dispositivo no ofrece. Prueba un Chrome, Firefox o Safari reciente, o activa la aceleración por hardware.',
    // The error's own text is English (a browser or library message): the console has it.
    startFailed: () => 'Oceano no pudo arrancar; el detalle técnico está en la consola del navegador.',
    boatPathInvalid: (v) => `"boat=${v.text}" no es una ruta de este sitio; se usa el barco incluido.`,
    boatLoadFailed: () => 'No se pudo cargar el barco; el detalle técnico está en la consola del navegador. El océano sigue sin él.',
    boatUnreachable: (v) => `No se pudo descargar el modelo del barco "${v.url}". El océano sigue sin él.`,
    boatNotFound: (v) => `No se encontró el modelo del barco "${v.url}" (HTTP ${v.status}). El océano sigue sin él.`,
    boatWebPage: (v) => `Falta el modelo del barco "${v.url}": el servidor envió una página web en su lugar. El océano sigue sin él.`,
    boatNotGltf: (v) => `El modelo del barco "${v.url}" no es un glTF válido: ni un .glb binario ni un .gltf JSON que three.js pueda leer. El océano sigue sin él.`,
    boatNoGeometry: (v) => `El modelo del barco "${v.url}" no tiene geometría que pueda flotar. El océano sigue sin él.`,
    boatStateInvalid: (v) => `"boatState=${v.text}" no son diez números finitos dentro de la zona del barco; el barco empieza de nuevo.`,
    wakeTrackInvalid: (v) => `"wakeTrack=${v.text}" no es una derrota grabada; la estela se reconstruye con el rumbo actual del barco.`,
    modelLoadFailed: (v) => `No se pudo descargar el código de las olas "${v.name}"; se sigue mostrando "${v.fallback}". Vuelve a elegirlas más tarde o recarga la página.`,
    underwaterLoadFailed: () => 'No se pudieron descargar los efectos bajo el agua (niebla, rayos de luz, desenfoque); el mar se ve desde abajo sin ellos. Recarga la página para intentarlo de nuevo.',
    elementAttributeInvalid: (v) => `"${v.name}=${v.text}" no es uno de ${v.allowed}; se usa "${v.fallback}".`,
    panelLoadFailed: () => 'No se pudo descargar el panel de controles; el océano sigue sin él. Recarga la página para intentarlo de nuevo.',
  },
};

/** Words of the interface that are not parameters or notices. */
export type UiTextId =
  | 'canvasLabel'
  | 'canvasLabelHeightmap'
  | 'canvasLabelNormals'
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
  | 'folderCompare'
  | 'compareDivider'
  | 'dive'
  | 'surface'
  | 'dropStone'
  | 'folderLiveCounts'
  | 'countChunks'
  | 'countTriangles'
  | 'countDrawCalls'
  | 'countPerBand'
  | 'loadingTitle'
  | 'loading_sky'
  | 'loading_firstFrame'
  | 'loading_boat'
  | 'froudeNumber'
  | 'play'
  | 'pause'
  | 'playing'
  | 'share'
  | 'dismiss'
  | 'fresnelPlotLabel'
  | 'fresnelTitle'
  | 'fresnelAxis'
  | 'fresnelExact'
  | 'fresnelSchlick';

const UI: Record<Language, Record<UiTextId, string>> = {
  en: {
    canvasLabel: 'Animated 3D ocean under a sky',
    canvasLabelHeightmap: 'The two heightmaps of the ripples, shown as greyscale images of their values',
    canvasLabelNormals: 'Animated 3D ocean coloured by its surface normals',
    panelTitle: 'Oceano',
    folderSwell: 'Swell',
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
    compareDivider: 'Divider between wave models (drag, or arrow keys)',
    dive: 'Dive under the surface',
    surface: 'Back to the surface view',
    dropStone: 'Drop a stone (interactive waves)',
    folderLiveCounts: 'LOD counts (live)',
    countChunks: 'Chunks visible / total',
    countTriangles: 'Triangles',
    countDrawCalls: 'Draw calls',
    countPerBand: 'Chunks per band',
    loadingTitle: 'Loading',
    loading_sky: 'sky',
    loading_firstFrame: 'sea and first frame',
    loading_boat: 'boat',
    froudeNumber: 'Froude number U/√(gL)',
    play: 'Play',
    pause: 'Pause',
    playing: 'Play',
    share: 'Share link',
    dismiss: 'Dismiss',
    fresnelPlotLabel: 'Plot of the Fresnel reflectance of water against the angle of incidence, exact and Schlick',
    fresnelTitle: 'Fresnel reflectance, air → water',
    fresnelAxis: 'angle of incidence',
    fresnelExact: 'exact (table uploaded to the GPU)',
    fresnelSchlick: 'Schlick’s approximation',
  },
  es: {
    canvasLabel: 'Océano 3D animado bajo un cielo',
    canvasLabelHeightmap: 'Los dos mapas de alturas de las ondas, como imágenes en escala de grises de sus valores',
    canvasLabelNormals: 'Océano 3D animado coloreado según las normales de su superficie',
    panelTitle: 'Oceano',
    folderSwell: 'Oleaje',
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
    compareDivider: 'Divisor entre modelos de olas (arrastrar o flechas)',
    dive: 'Sumergirse',
    surface: 'Volver a la superficie',
    dropStone: 'Tirar una piedra (olas interactivas)',
    folderLiveCounts: 'Contadores de LOD (en vivo)',
    countChunks: 'Parcelas visibles / total',
    countTriangles: 'Triángulos',
    countDrawCalls: 'Llamadas de dibujo',
    countPerBand: 'Parcelas por banda',
    loadingTitle: 'Cargando',
    loading_sky: 'cielo',
    loading_firstFrame: 'mar y primer fotograma',
    loading_boat: 'barco',
    froudeNumber: 'Número de Froude U/√(gL)',
    play: 'Reproducir',
    pause: 'Pausar',
    playing: 'Reproducir',
    share: 'Compartir enlace',
    dismiss: 'Cerrar',
    fresnelPlotLabel: 'Gráfico de la reflectancia de Fresnel del agua según el ángulo de incidencia, exacta y de Schlick',
    fresnelTitle: 'Reflectancia de Fresnel, aire → agua',
    fresnelAxis: 'ángulo de incidencia',
    fresnelExact: 'exacta (tabla subida a la GPU)',
    fresnelSchlick: 'aproximación de Schlick',
  },
};

/**
 * Spanish labels of the parameters; English ones live next to each definition in
 * params.ts. Typed as a full record, so a parameter without one does not compile.
 */
export const SPANISH_PARAM_LABELS: Record<ParamKey, string> = {
  waves: 'Modelo de olas',
  compare: 'Comparar modelos lado a lado',
  compareSplit: 'Comparar: primer divisor',
  compareSplit2: 'Comparar: segundo divisor',
  windSpeed: 'Velocidad del viento U10',
  windDirection: 'Dirección del viento',
  spectrum: 'Espectro de oleaje',
  fetch: 'Fetch (JONSWAP)',
  depth: 'Profundidad (dispersión)',
  spreading: 'Dispersión direccional s (cos-2s)',
  spreadingModel: 'Modelo de dispersión direccional',
  choppiness: 'Crestas afiladas λ',
  fftSize: 'Tamaño de la FFT',
  foam: 'Espuma',
  foamThreshold: 'Sesgo del umbral de espuma (jacobiano)',
  foamFade: 'Vida de la espuma τ',
  foamTexture: 'Textura de la espuma',
  subsurface: 'Brillo de las crestas',
  normalsCompare: 'Comparar normales de pendiente | fabricadas',
  seed: 'Semilla del ruido',
  swellAmplitude: 'Amplitud del oleaje',
  swellFrequency: 'Frecuencia del oleaje',
  rippleStrength: 'Intensidad de las ondas',
  rippleBlendSpeed: 'Velocidad de mezcla de las ondas',
  sunElevation: 'Elevación del sol',
  sunAzimuth: 'Acimut del sol',
  waterColor: 'Color del agua profunda',
  fresnel: 'Fresnel',
  wireframe: 'Malla de alambre',
  shading: 'Sombreado',
  normals: 'Normales',
  view: 'Vista',
  fresnelPlot: 'Gráfico de Fresnel',
  timeScale: 'Velocidad (escala de tiempo)',
  physics: 'Panel de física',
  boatSpeed: 'Velocidad del barco',
  boatHeading: 'Rumbo del barco',
  boatResponse: 'Tiempo de respuesta de flotación',
  boatFollow: 'La cámara sigue al barco',
  boatTurnRate: 'Velocidad de giro del barco',
  wake: 'Estela de Kelvin',
  wakeStrength: 'Intensidad de la estela',
  wakeGuide: 'Guía del ángulo de Kelvin (±19,47°)',
  interactiveWaves: 'Olas interactivas (iWave)',
  lodDistance: 'Distancia de LOD L',
  lodBands: 'Bandas de LOD',
  lodColors: 'Colorear parcelas por banda',
  lodMorph: 'Geomorfismo (transición suave entre bandas)',
  freezeCulling: 'Congelar el recorte',
  lodBruteForce: 'Fuerza bruta (malla completa, sin recorte)',
  blurStrength: 'Desenfoque bajo el agua (σ)',
  fogDensity: 'Densidad de la niebla del agua',
  seaBedDepth: 'Profundidad del fondo',
  caustics: 'Cáusticas',
  causticsIntensity: 'Intensidad de las cáusticas',
  godRays: 'Rayos de luz',
  godRaysIntensity: 'Intensidad de los rayos de luz',
  gerstnerCount: 'Ondas de Gerstner',
  gerstnerSteepness: 'Pendiente de Gerstner Q',
};

/** What the canvas shows, for its aria-label: it follows the teaching view. */
export function canvasLabel(tr: Translator, params: Pick<OceanParams, 'view' | 'shading'>): string {
  if (params.view === 'heightmap') return tr.ui('canvasLabelHeightmap');
  return tr.ui(params.shading === 'normals' ? 'canvasLabelNormals' : 'canvasLabel');
}

/** Everything the page says, in one language. */
export class Translator {
  constructor(readonly language: Language) {}

  message(m: Message): string {
    return MESSAGES[this.language][m.id](m.values);
  }

  ui(id: UiTextId): string {
    return UI[this.language][id];
  }

  paramLabel(key: ParamKey): string {
    return this.language === 'es' ? SPANISH_PARAM_LABELS[key] : paramDefs[key].label;
  }
}
