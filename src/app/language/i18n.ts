import type { OceanParams } from '../../sim/params/params';
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

export type Render = (v: MessageValues) => string;
/** Inner text ended with exactly one full stop, so "…404)." never becomes "…404).)" or "..". */
const sentence = (text: string | number | boolean | undefined) =>
  `${String(text ?? '')
    .trim()
    .replace(/[.\s]+$/, '')}.`;
const unit = (v: MessageValues) => (v.unit ? ` ${v.unit}` : '');

/**
 * Notices that only a part fetched on use can raise: their texts travel in that part and are
 * added here when it loads (registerNoticeTexts), so the page's first script does not carry them.
 */
export type LateNoticeId = 'boatUnreachable' | 'boatNotFound' | 'boatWebPage' | 'boatNotGltf' | 'boatNoGeometry' | 'boatAground';

const MESSAGES: Record<Language, Record<Exclude<MessageId, LateNoticeId>, Render> & Partial<Record<LateNoticeId, Render>>> = {
  en: {
    paramNotBoolean: (v) => `"${v.key}=${v.text}" is not true/false; using ${v.fallback}.`,
    paramNotColour: (v) => `"${v.key}=${v.text}" is not a colour like 0a2e45; using ${v.fallback}.`,
    paramNotChoice: (v) => `"${v.key}=${v.text}" is not one of ${v.options}; using ${v.fallback}.`,
    paramNotInteger: (v) => `"${v.key}=${v.text}" is not an integer; using the default ${v.fallback}.`,
    paramNotNumber: (v) => `"${v.key}=${v.text}" is not a number; using the default ${v.fallback}.`,
    paramClamped: (v) => `"${v.key}=${v.text}" is outside [${v.min}, ${v.max}]${unit(v)}; clamped to ${v.clamped}.`,
    timeInvalid: (v) => `"t=${v.text}" is not a time in seconds between 0 and 1e9; the animation runs from 0 instead.`,
    skyInvalid: (v) => `"sky=${v.text}" is not a path on this site; using the built-in sky.`,
    cameraInvalid: (v) =>
      `"cam=${v.text}" is not six finite numbers x,y,z,tx,ty,tz (target apart from the position, each within ±1e6 m); using the default camera.`,
    languageInvalid: (v) => `"lang=${v.text}" is not a language we speak (en, es); using the browser's language.`,
    embedInvalid: (v) => `"embed=${v.text}" is not 1 or 0; showing the full page.`,
    presetUnknown: (v) => `There is no preset "${v.name}"; showing the default view. Presets: ${v.known}.`,
    lessonUnknown: (v) => `There is no lesson "${v.name}"; nothing was changed. Lessons: ${v.known}.`,
    unknownUrlParam: (v) => `Unknown URL parameter "${v.key}" was ignored.`,
    skyLoadFailed: (v) => `The sky images under "${v.base}" could not be loaded. Showing the sky painted from the sun instead.`,
    skyCustomSunFixed: (v) =>
      `Showing the sky images under "${v.base}": their sun is painted in, so the sun's direction now moves only the lighting and the glint on the water.`,
    contextLost: () =>
      'The graphics context was lost: the GPU was reset, or this page holds more 3D views than the browser keeps alive (about 16). The ocean comes back if the browser restores the context; if it does not, reload the page.',
    shareCopied: () => 'Link to this view copied to the clipboard.',
    shareFallback: (v) => `Copy this link to share the view: ${v.url}`,
    webgl2Missing: () =>
      'Oceano needs WebGL2, which this browser or device does not provide. Try a recent Chrome, Firefox or Safari, or enable hardware acceleration.',
    startFailed: (v) => `Oceano could not start: ${sentence(v.error)}`,
    boatPathInvalid: (v) => `"boat=${v.text}" is not a path on this site; using the built-in boat.`,
    boatLoadFailed: (v) => `The boat could not be loaded: ${sentence(v.reason)} The ocean runs without the boat.`,
    boatStateInvalid: (v) => `"boatState=${v.text}" is not ten finite numbers within the boat's area; the boat starts afresh.`,
    wakeTrackInvalid: (v) => `"wakeTrack=${v.text}" is not a recorded track; the wake is replayed from the boat's present course.`,
    modelLoadFailed: (v) =>
      `The code of the "${v.name}" waves could not be downloaded; still showing "${v.fallback}". Choose it again later, or reload the page.`,
    underwaterLoadFailed: () =>
      'The underwater effects (water fog, light shafts, blur) could not be downloaded; the sea is drawn from below without them. Reload the page to try again.',
    elementAttributeInvalid: (v) => `"${v.name}=${v.text}" is not one of ${v.allowed}; using "${v.fallback}".`,
    panelLoadFailed: () => 'The control panel could not be downloaded; the ocean runs without it. Reload the page to try again.',
    disturbInvalid: (v) => `disturb: ${v.name} = ${v.got} is not in [${v.min}, ${v.max}] m; no stone dropped.`,
    disturbRadiusRaised: (v) => `disturb: radius ${v.radius} m is under one texel; raised to ${v.raised} m.`,
    disturbFieldOff: () => 'disturb: the interactive waves are off.',
    stonesInvalid: (v) => `"stones=${v.text}" is not a list of t,x,z,radius,height in range; no stones.`,
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
    cameraInvalid: (v) =>
      `"cam=${v.text}" no son seis números finitos x,y,z,tx,ty,tz (objetivo distinto de la posición, cada uno dentro de ±1e6 m); se usa la cámara por defecto.`,
    languageInvalid: (v) => `"lang=${v.text}" no es un idioma disponible (en, es); se usa el idioma del navegador.`,
    embedInvalid: (v) => `"embed=${v.text}" no es 1 ni 0; se muestra la página completa.`,
    presetUnknown: (v) => `No existe la vista predefinida "${v.name}"; se muestra la vista por defecto. Disponibles: ${v.known}.`,
    lessonUnknown: (v) => `No existe la lección "${v.name}"; no se ha cambiado nada. Lecciones: ${v.known}.`,
    unknownUrlParam: (v) => `Se ignoró el parámetro de URL desconocido "${v.key}".`,
    skyLoadFailed: (v) => `No se pudieron cargar las imágenes del cielo en "${v.base}". Se muestra el cielo pintado a partir del sol.`,
    skyCustomSunFixed: (v) =>
      `Se muestran las imágenes del cielo en "${v.base}": su sol está pintado en ellas, así que la dirección del sol solo mueve la iluminación y el brillo en el agua.`,
    contextLost: () =>
      'Se perdió el contexto gráfico: la GPU se reinició, o esta página tiene más vistas 3D de las que el navegador mantiene (unas 16). El océano vuelve si el navegador restablece el contexto; si no, recarga la página.',
    shareCopied: () => 'Enlace a esta vista copiado al portapapeles.',
    shareFallback: (v) => `Copia este enlace para compartir la vista: ${v.url}`,
    webgl2Missing: () =>
      'Oceano necesita WebGL2, que este navegador o dispositivo no ofrece. Prueba un Chrome, Firefox o Safari reciente, o activa la aceleración por hardware.',
    // The error's own text is English (a browser or library message): the console has it.
    startFailed: () => 'Oceano no pudo arrancar; el detalle técnico está en la consola del navegador.',
    boatPathInvalid: (v) => `"boat=${v.text}" no es una ruta de este sitio; se usa el barco incluido.`,
    boatLoadFailed: () => 'No se pudo cargar el barco; el detalle técnico está en la consola del navegador. El océano sigue sin él.',
    boatStateInvalid: (v) => `"boatState=${v.text}" no son diez números finitos dentro de la zona del barco; el barco empieza de nuevo.`,
    wakeTrackInvalid: (v) => `"wakeTrack=${v.text}" no es una derrota grabada; la estela se reconstruye con el rumbo actual del barco.`,
    modelLoadFailed: (v) =>
      `No se pudo descargar el código de las olas "${v.name}"; se sigue mostrando "${v.fallback}". Vuelve a elegirlas más tarde o recarga la página.`,
    underwaterLoadFailed: () =>
      'No se pudieron descargar los efectos bajo el agua (niebla, rayos de luz, desenfoque); el mar se ve desde abajo sin ellos. Recarga la página para intentarlo de nuevo.',
    elementAttributeInvalid: (v) => `"${v.name}=${v.text}" no es uno de ${v.allowed}; se usa "${v.fallback}".`,
    panelLoadFailed: () =>
      'No se pudo descargar el panel de controles; el océano sigue sin él. Recarga la página para intentarlo de nuevo.',
    disturbInvalid: (v) => `disturb: ${v.name} = ${v.got} no está en [${v.min}, ${v.max}] m; no se tira la piedra.`,
    disturbRadiusRaised: (v) => `disturb: el radio ${v.radius} m es menor que un texel; se sube a ${v.raised} m.`,
    disturbFieldOff: () => 'disturb: las olas interactivas están apagadas.',
    stonesInvalid: (v) => `"stones=${v.text}" no es una lista de t,x,z,radio,altura en rango; sin piedras.`,
  },
};

/** Adds the texts of a part's own notices, in both languages; called by that part as it loads. */
export function registerNoticeTexts<Id extends LateNoticeId>(texts: Record<Language, Record<Id, Render>>): void {
  for (const language of LANGUAGES) Object.assign(MESSAGES[language], texts[language]);
}

/** Words of the interface that are not parameters or notices. */
export type UiTextId =
  | 'canvasLabel'
  | 'canvasLabelFigure'
  | 'canvasLabelNormals'
  | 'compareDivider'
  | 'loadingTitle'
  | 'loading_sky'
  | 'loading_firstFrame'
  | 'loading_boat'
  | 'play'
  | 'pause'
  | 'dismiss';

const UI: Record<Language, Record<UiTextId, string>> = {
  en: {
    canvasLabel: 'Animated 3D ocean under a sky',
    canvasLabelFigure:
      'A teaching figure in place of the sea: the heightmaps, the steps of their Perlin noise, or the sky’s cube map unfolded',
    canvasLabelNormals: 'Animated 3D ocean coloured by its surface normals',
    compareDivider: 'Divider between wave models (drag, or arrow keys)',
    loadingTitle: 'Loading',
    loading_sky: 'sky',
    loading_firstFrame: 'sea and first frame',
    loading_boat: 'boat',
    play: 'Play',
    pause: 'Pause',
    dismiss: 'Dismiss',
  },
  es: {
    canvasLabel: 'Océano 3D animado bajo un cielo',
    canvasLabelFigure:
      'Una figura didáctica en lugar del mar: los mapas de alturas, los pasos de su ruido de Perlin o el cube map del cielo desplegado',
    canvasLabelNormals: 'Océano 3D animado coloreado según las normales de su superficie',
    compareDivider: 'Divisor entre modelos de olas (arrastrar o flechas)',
    loadingTitle: 'Cargando',
    loading_sky: 'cielo',
    loading_firstFrame: 'mar y primer fotograma',
    loading_boat: 'barco',
    play: 'Reproducir',
    pause: 'Pausar',
    dismiss: 'Cerrar',
  },
};

/** What the canvas shows, for its aria-label: it follows the teaching view. */
export function canvasLabel(tr: Translator, params: Pick<OceanParams, 'view' | 'shading'>): string {
  if (params.view !== 'ocean') return tr.ui('canvasLabelFigure');
  return tr.ui(params.shading === 'normals' ? 'canvasLabelNormals' : 'canvasLabel');
}

/** Everything the page says, in one language. */
export class Translator {
  constructor(readonly language: Language) {}

  message(m: Message): string {
    const render: Render | undefined = MESSAGES[this.language][m.id];
    if (!render) throw new Error(`The text of the notice "${m.id}" comes with the part that raises it, which has not loaded.`);
    return render(m.values);
  }

  ui(id: UiTextId): string {
    return UI[this.language][id];
  }
}
