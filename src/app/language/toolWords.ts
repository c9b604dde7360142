import type { Language, Translator } from './i18n';

/**
 * The words of the sea tools (probe, ruler, stones), es/en. Only the tools' chunk, fetched
 * when they are first used, reads them, so they stay out of the page's first script.
 */
const EN = {
  title: 'Sea tools',
  close: 'Close the sea tools',
  choice: 'Tool',
  none: 'None',
  probe: 'Probe',
  ruler: 'Ruler',
  disturb: 'Stones',
  helpNone: 'Choose a tool, then click or drag on the sea. Dragging the sky still turns the camera.',
  helpProbe:
    'Click the sea to place the probe: the chart shows the height there over the last 30 s of simulated time. Keyboard: focus “Place with the keys”, move with the arrows (Shift: 10 cm steps), Enter places it.',
  helpRuler:
    'Drag across the sea to measure the distance seen from above. Keyboard: focus “Place with the keys”, move with the arrows (Shift: 10 cm steps), Enter fixes the first end, Enter again the second.',
  helpDisturb:
    'Click or drag on the sea to drop stones into the interactive waves. Keyboard: focus “Place with the keys”, move with the arrows, Enter drops a stone; or drop one at the centre of the view.',
  howTo: 'How to use it',
  aboutTheory: 'About the theory',
  keys: 'Place with the keys',
  keysLabel: 'Point on the sea: {x}, {z} m. Arrows move it, Enter uses it.',
  dropCentre: 'Drop a stone at the centre',
  probeNone: 'No probe yet: click the sea.',
  probeAt: 'Probe at x = {x} m, z = {z} m',
  probeRemove: 'Remove the probe',
  remove: 'Remove',
  rulerRemove: 'Remove the ruler',
  quantity: 'Quantity',
  measured: 'Measured',
  theory: 'Theory',
  periodTz: 'Period Tz',
  crestTrough: 'Crest to trough',
  hs: 'Hs = 4σ',
  peakPeriod: 'Peak period Tp = 2π/ωp',
  swellFormula: 'swell formula',
  swellNote:
    'Tz is the mean time between the moments the water rises through its mean level. The swell is built with ω = √(g k) = {omega} rad/s, 2π/ω = {period} s. A point does not rise once every 2π/ω: sin(kx + ωt)·cos(kz + 0.7ωt) = ½ sin(kx + kz + 1.7ωt) + ½ sin(kx − kz + 0.3ωt), and the second product adds two more waves. Theory is the swell’s formula alone, at this point and these times; the ripples and stones are what differ.',
  spectrumNote:
    'Tz is the mean time between the moments the water rises through its mean level. Theory from the wind spectrum S(ω): Tz = 2π√(m₀/m₂) (Rice), Hs = 4√m₀. 30 s hold only a few waves: the measured figures scatter by about ±20 %.',
  waiting: 'Tz needs two up-crossings in the record: let the sea run.',
  chartTime: 'time (s)',
  chartHeight: 'η (m)',
  rulerNone: 'No ruler yet: drag across the sea.',
  rulerDistance: 'Distance seen from above: {d} m',
  rulerEnds: 'From ({ax}, {az}) to ({bx}, {bz}) m',
  rulerFirst: 'First end fixed: move to the second end and press Enter.',
  stoneDropped: 'Stones dropped: {n}',
  wavesOn: 'The interactive waves were off: the stones tool turned them on.',
  probeInvalid: '"probe={text}" is not two finite numbers x,z in metres (each within ±1e6); no probe was placed.',
  probeArgs: 'probe needs (x, z) in metres (finite numbers within ±1e6), null to remove it, or nothing to read it.',
};

export type ToolWordId = keyof typeof EN;

const ES: Record<ToolWordId, string> = {
  title: 'Herramientas del mar',
  close: 'Cerrar las herramientas',
  choice: 'Herramienta',
  none: 'Ninguna',
  probe: 'Sonda',
  ruler: 'Regla',
  disturb: 'Piedras',
  helpNone: 'Elige una herramienta y haz clic o arrastra sobre el mar. Arrastrar el cielo sigue girando la cámara.',
  helpProbe:
    'Haz clic en el mar para poner la sonda: la gráfica muestra la altura allí durante los últimos 30 s de tiempo simulado. Teclado: enfoca «Colocar con las teclas», muévete con las flechas (Mayús: pasos de 10 cm) y pulsa Intro para ponerla.',
  helpRuler:
    'Arrastra sobre el mar para medir la distancia vista desde arriba. Teclado: enfoca «Colocar con las teclas», muévete con las flechas (Mayús: pasos de 10 cm); Intro fija el primer extremo e Intro otra vez el segundo.',
  helpDisturb:
    'Haz clic o arrastra sobre el mar para dejar caer piedras en las olas interactivas. Teclado: enfoca «Colocar con las teclas», muévete con las flechas e Intro deja caer una piedra; o deja caer una en el centro de la vista.',
  howTo: 'Cómo se usa',
  aboutTheory: 'Sobre la teoría',
  keys: 'Colocar con las teclas',
  keysLabel: 'Punto del mar: {x}, {z} m. Las flechas lo mueven, Intro lo usa.',
  dropCentre: 'Dejar caer una piedra en el centro',
  probeNone: 'Aún no hay sonda: haz clic en el mar.',
  probeAt: 'Sonda en x = {x} m, z = {z} m',
  probeRemove: 'Quitar la sonda',
  remove: 'Quitar',
  rulerRemove: 'Quitar la regla',
  quantity: 'Magnitud',
  measured: 'Medido',
  theory: 'Teoría',
  periodTz: 'Periodo Tz',
  crestTrough: 'De cresta a valle',
  hs: 'Hs = 4σ',
  peakPeriod: 'Periodo de pico Tp = 2π/ωp',
  swellFormula: 'fórmula del oleaje',
  swellNote:
    'Tz es el tiempo medio entre los momentos en que el agua sube a través de su nivel medio. El oleaje se construye con ω = √(g k) = {omega} rad/s, 2π/ω = {period} s. Un punto no sube una vez cada 2π/ω: sen(kx + ωt)·cos(kz + 0,7ωt) = ½ sen(kx + kz + 1,7ωt) + ½ sen(kx − kz + 0,3ωt), y el segundo producto suma otras dos ondas. La teoría es la fórmula del oleaje sola, en este punto y en estos instantes; lo que difiere son las ondulaciones y las piedras.',
  spectrumNote:
    'Tz es el tiempo medio entre los momentos en que el agua sube a través de su nivel medio. Teoría a partir del espectro del viento S(ω): Tz = 2π√(m₀/m₂) (Rice), Hs = 4√m₀. En 30 s caben pocas olas: lo medido se dispersa en torno a ±20 %.',
  waiting: 'Tz necesita dos cruces ascendentes en el registro: deja correr el mar.',
  chartTime: 'tiempo (s)',
  chartHeight: 'η (m)',
  rulerNone: 'Aún no hay regla: arrastra sobre el mar.',
  rulerDistance: 'Distancia vista desde arriba: {d} m',
  rulerEnds: 'De ({ax}, {az}) a ({bx}, {bz}) m',
  rulerFirst: 'Primer extremo fijado: ve al segundo y pulsa Intro.',
  stoneDropped: 'Piedras lanzadas: {n}',
  wavesOn: 'Las olas interactivas estaban apagadas: la herramienta de piedras las encendió.',
  probeInvalid: '"probe={text}" no son dos números finitos x,z en metros (cada uno dentro de ±1e6); no se puso ninguna sonda.',
  probeArgs: 'probe necesita (x, z) en metros (números finitos dentro de ±1e6), null para quitarla, o nada para leerla.',
};

const WORDS: Record<Language, Record<ToolWordId, string>> = { en: EN, es: ES };

/** A tool word in the translator's language, with {name} filled from `values`. */
export function toolWord(tr: Pick<Translator, 'language'>, id: ToolWordId, values: Record<string, string | number> = {}): string {
  return WORDS[tr.language][id].replace(/\{(\w+)\}/g, (_, name: string) => String(values[name] ?? `{${name}}`));
}

/** A number written as the page's language writes it (a decimal comma in Spanish). */
export function toolNumber(tr: Pick<Translator, 'language'>, value: number, digits: number): string {
  if (!Number.isFinite(value)) return '—';
  const text = value.toFixed(digits);
  return tr.language === 'es' ? text.replace('.', ',') : text;
}
