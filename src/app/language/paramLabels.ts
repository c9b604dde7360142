import { paramDefs, type ParamKey } from '../../sim/params/params';
import type { Translator } from './i18n';

/**
 * Spanish labels of the parameters; English ones live next to each definition in
 * params.ts. Typed as a full record, so a parameter without one does not compile. Only the
 * control panel and the lesson cards name parameters, so these travel in their chunks, not
 * in the page's first script.
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
  foamFade: 'Decaimiento de la espuma τ',
  foamTexture: 'Textura de la espuma',
  waveGroups: 'Grupos de olas',
  windrows: 'Hileras de espuma',
  subsurface: 'Brillo bajo la superficie',
  visibility: 'Visibilidad (calima)',
  exposure: 'Exposición',
  normalsCompare: 'Comparar normales de pendiente | fabricadas',
  seed: 'Semilla del ruido',
  swellAmplitude: 'Amplitud del oleaje',
  swellFrequency: 'Frecuencia del oleaje',
  rippleStrength: 'Intensidad de las ondas',
  rippleBlendSpeed: 'Velocidad de mezcla de las ondas',
  sunElevation: 'Elevación del sol',
  sunAzimuth: 'Acimut del sol',
  waterColor: 'Color del agua profunda',
  waterColorPicked: 'Usar el color de agua elegido',
  fresnel: 'Fresnel',
  seaRoughness: 'Rugosidad (Cox y Munk)',
  skyBlur: 'Cielo difuminado por la rugosidad',
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
  iwaveEquation: 'Olas interactivas: ecuación',
  iwaveGuide: 'Anillos donde la teoría pone las crestas',
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

/** A parameter's name in the translator's language. */
export function paramLabel(tr: Pick<Translator, 'language'>, key: ParamKey): string {
  return tr.language === 'es' ? SPANISH_PARAM_LABELS[key] : paramDefs[key].label;
}
