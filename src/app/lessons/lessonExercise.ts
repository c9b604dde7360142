import type { Language } from '../language/i18n';
import type { OceanParams } from '../../sim/params/params';
import { WAVE_EQUATION_SPEED } from '../../sim/iwave/interactiveField';
import { GRAVITY } from '../../sim/waves/dispersion';
import {
  exerciseFor,
  withinTolerance,
  type ExerciseMoment,
  type ExerciseQuantity,
  type MeasurementExercise,
} from '../../sim/teaching/measurementExercises';

type Words = Record<Language, string>;

/** What the student is asked to do, by quantity: which tool, where to read it. */
const TASKS: Record<ExerciseQuantity, Words> = {
  significantHeight: {
    en: 'Open the physics panel (Physics panel in the controls) and read the significant wave height Hs = 4σ(η) it measured on this sea, in the “measured” column. Type it here.',
    es: 'Abre el panel de física (Physics panel en los controles) y lee la altura significativa Hs = 4σ(η) que midió en este mar, en la columna “measured”. Escríbela aquí.',
  },
  wavesSignificantHeight: {
    en: 'Open the physics panel (Physics panel in the controls) and read the significant wave height Hs = 4σ(η) it measured on these Gerstner waves, in the “measured” column. Type it here.',
    es: 'Abre el panel de física (Physics panel en los controles) y lee la altura significativa Hs = 4σ(η) que midió sobre estas olas de Gerstner, en la columna “measured”. Escríbela aquí.',
  },
  peakPeriod: {
    en: 'Open the physics panel (Physics panel in the controls) and read the peak period Tp it measured on this sea, in the “measured” column. Type it here.',
    es: 'Abre el panel de física (Physics panel en los controles) y lee el período de pico Tp que midió en este mar, en la columna “measured”. Escríbelo aquí.',
  },
  transverseWavelength: {
    en: 'Pause, open the sea tools (Sea tools in the panel), choose the ruler and lay it along the boat’s track behind it, from one transverse crest to a crest a few waves further. Divide by the number of waves and type the wavelength λ.',
    es: 'Pausa, abre las herramientas del mar (Sea tools en el panel), elige la regla y tiéndela sobre la estela detrás del barco, de una cresta transversal a otra unas olas más allá. Divide por el número de olas y escribe la longitud de onda λ.',
  },
  turningRadius: {
    en: 'Note where the boat is now, let it run until it heads the opposite way (half a turn: a minute at 3°/s, 9 s at 20°/s) and pause. Open the sea tools (Sea tools in the panel), choose the ruler and lay it from the spot where it started to the boat: that is the circle’s diameter. Type the radius R.',
    es: 'Fíjate dónde está el barco ahora, déjalo avanzar hasta que navegue en sentido contrario (media vuelta: un minuto a 3°/s, 9 s a 20°/s) y pausa. Abre las herramientas del mar (Sea tools en el panel), elige la regla y tiéndela desde el punto donde empezó hasta el barco: es el diámetro del círculo. Escribe el radio R.',
  },
  ringRadius: {
    en: 'Pause while the ring of the plain wave equation (the right-hand stone) is clear of its stone. Turn off the yellow rings, open the sea tools (Sea tools in the panel), choose the ruler and lay it from where that stone fell to its ring’s crest. Type the radius r.',
    es: 'Pausa mientras el anillo de la ecuación de onda simple (la piedra de la derecha) está lejos de su piedra. Apaga los anillos amarillos, abre las herramientas del mar (Sea tools en el panel), elige la regla y tiéndela desde donde cayó esa piedra hasta la cresta de su anillo. Escribe el radio r.',
  },
  groupDistance: {
    en: 'Pause 10 to 15 s after the stone. The outermost yellow ring marks the longest waves the grid carries; with the sea tools’ ruler (Sea tools in the panel) measure from where the stone fell to the real crest beside that ring: how far that group has run. Type r.',
    es: 'Pausa entre 10 y 15 s después de la piedra. El anillo amarillo más exterior marca las olas más largas que lleva la malla; con la regla de las herramientas del mar (Sea tools en el panel) mide desde donde cayó la piedra hasta la cresta real junto a ese anillo: lo que ha recorrido ese grupo. Escribe r.',
  },
  crestSpacing: {
    en: 'About 12 s after the stone falls, pause. The yellow rings mark where theory puts the crests; turn them off and, with the sea tools’ ruler (Sea tools in the panel), lay it from the outermost crest they marked to the next crest inward. Type that spacing Δr.',
    es: 'Unos 12 s después de caer la piedra, pausa. Los anillos amarillos marcan dónde pone la teoría las crestas; apágalos y, con la regla de las herramientas del mar (Sea tools en el panel), tiéndela desde la cresta más exterior que marcaban hasta la siguiente hacia dentro. Escribe esa separación Δr.',
  },
};

/** How the theory follows, with the live values filled in. */
function theoryLine(exercise: MeasurementExercise, params: OceanParams, moment: ExerciseMoment, language: Language): string {
  const es = language === 'es';
  switch (exercise.quantity) {
    case 'significantHeight':
      return es
        ? `Hs = 4√m₀, con m₀ = ∫S(ω)dω del espectro ${params.spectrum} a U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` y ${params.fetch} km de fetch` : ''}`
        : `Hs = 4√m₀, m₀ = ∫S(ω)dω of the ${params.spectrum} spectrum at U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` over a ${params.fetch} km fetch` : ''}`;
    case 'wavesSignificantHeight':
      return es
        ? `una suma de senos de amplitudes Aᵢ tiene varianza Σ Aᵢ²/2, así que Hs = 4√(Σ Aᵢ²/2) sobre las ${params.gerstnerCount} olas dibujadas`
        : `a sum of sines of amplitudes Aᵢ has the variance Σ Aᵢ²/2, so Hs = 4√(Σ Aᵢ²/2) over the ${params.gerstnerCount} waves drawn`;
    case 'peakPeriod':
      return es
        ? `Tp = 2π/ωp, ωp el pico del espectro ${params.spectrum} a U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` y ${params.fetch} km de fetch` : ''}`
        : `Tp = 2π/ωp, ωp the peak of the ${params.spectrum} spectrum at U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` over a ${params.fetch} km fetch` : ''}`;
    case 'transverseWavelength':
      return es
        ? `las olas transversales acompañan al barco: c = √(g/k) = U, k = g/U², λ = 2πU²/g con U = ${params.boatSpeed} m/s`
        : `the transverse waves keep pace with the boat: c = √(g/k) = U, so k = g/U², λ = 2πU²/g with U = ${params.boatSpeed} m/s`;
    case 'turningRadius':
      return es
        ? `a velocidad U girando a ω rad/s el barco recorre un círculo de radio R = U/ω, con U = ${params.boatSpeed} m/s y ω = ${params.boatTurnRate}°/s = ${((params.boatTurnRate * Math.PI) / 180).toFixed(4).replace('.', ',')} rad/s`
        : `at speed U turning at ω rad/s the boat runs on a circle of radius R = U/ω, U = ${params.boatSpeed} m/s, ω = ${params.boatTurnRate}°/s = ${((params.boatTurnRate * Math.PI) / 180).toFixed(4)} rad/s`;
    case 'ringRadius': {
      const t = (moment.stoneAge ?? 0).toFixed(2);
      const c = WAVE_EQUATION_SPEED.toFixed(2);
      return es
        ? `la ecuación de onda lleva todas las longitudes de onda a la misma velocidad c = ${c.replace('.', ',')} m/s: el anillo está en r = c t, t = ${t.replace('.', ',')} s desde la piedra`
        : `the wave equation carries every wavelength at one speed c = ${c} m/s: the ring stands at r = c t, t = ${t} s since the stone`;
    }
    case 'groupDistance': {
      const t = moment.stoneAge ?? 0;
      // The crest at r is the n-th of Cauchy–Poisson's r_n = g t²/(8πn).
      const n = Math.round((GRAVITY * t * t) / (8 * Math.PI * exercise.expected(params, moment)));
      const k = (16 * Math.PI * Math.PI * n * n) / (GRAVITY * t * t);
      const text = es
        ? `la energía de las olas de número de onda k viaja a c_g = ½√(g/k); la cresta exterior es la n = ${n}, k = 16π²n²/(g t²) = ${k.toFixed(3)} rad/m, así que r = c_g t con t = ${t.toFixed(2)} s`
        : `the energy of waves of wavenumber k travels at c_g = ½√(g/k); the outer crest is n = ${n}, k = 16π²n²/(g t²) = ${k.toFixed(3)} rad/m, so r = c_g t with t = ${t.toFixed(2)} s`;
      return es ? text.replace(/(\d)\.(\d)/g, '$1,$2') : text;
    }
    case 'crestSpacing': {
      const t = (moment.stoneAge ?? 0).toFixed(2);
      return es
        ? `Cauchy–Poisson: las crestas están en r_n = g t²/(8πn), t = ${t.replace('.', ',')} s desde la piedra; Δr = r_n − r_(n+1) entre las dos más exteriores que lleva la malla`
        : `Cauchy–Poisson: the crests stand at r_n = g t²/(8πn), t = ${t} s since the stone; Δr = r_n − r_(n+1) for the two outermost the grid carries`;
    }
  }
}

const WORDS = {
  heading: { en: 'Measure it', es: 'Mídelo' },
  check: { en: 'Check', es: 'Comprobar' },
  within: { en: 'Within tolerance', es: 'Dentro de la tolerancia' },
  notYet: { en: 'Not yet', es: 'Todavía no' },
  theory: { en: 'theory', es: 'teoría' },
  tolerance: { en: 'tolerance', es: 'tolerancia' },
  empty: { en: 'Type a number first.', es: 'Escribe primero un número.' },
  noTheory: {
    en: 'Nothing to compare yet: no stone has fallen, or its crests have left the grid.',
    es: 'Aún no hay con qué comparar: no ha caído ninguna piedra, o sus crestas ya salieron de la malla.',
  },
} satisfies Record<string, Words>;

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  el.className = className;
  if (text !== undefined) el.textContent = text;
  return el;
}

/** Numbers typed with a decimal comma (the Spanish way) are read too. */
function parseTyped(text: string): number {
  const trimmed = text.trim().replace(',', '.');
  return trimmed === '' ? Number.NaN : Number(trimmed);
}

/**
 * The card's measurement exercise for `lesson` (null if it has none): the task, a number field
 * with its unit, a Check button (Enter in the field checks too) and a result line read out
 * (aria-live): within tolerance or not yet, then the theory's value from the parameters of
 * the moment (`params()`, and `moment()`: how long ago the stone fell) and how it follows.
 */
export function lessonExercise(
  lesson: string,
  language: Language,
  params: () => OceanParams | null,
  moment: () => ExerciseMoment = () => ({ stoneAge: null }),
): HTMLElement | null {
  const exercise = exerciseFor(lesson);
  if (!exercise) return null;
  const root = element('section', 'oceano-lesson-exercise');
  root.dataset.exercise = exercise.quantity;
  const headingId = `oceano-exercise-${Math.random().toString(36).slice(2)}`;
  const heading = element('h3', 'oceano-lesson-exercise-title', WORDS.heading[language]);
  heading.id = headingId;
  root.setAttribute('aria-labelledby', headingId);
  const task = element('p', 'oceano-lesson-exercise-task', TASKS[exercise.quantity][language]);
  const tolerance = element(
    'p',
    'oceano-lesson-exercise-tolerance',
    `${WORDS.tolerance[language]}: ±${Math.round(exercise.tolerance * 100)} %`,
  );
  const form = element('form', 'oceano-lesson-exercise-form');
  const label = element('label', 'oceano-lesson-exercise-label');
  label.append(element('span', '', `${exercise.symbol} =`));
  const field = element('input', 'oceano-lesson-exercise-value');
  field.type = 'text';
  field.inputMode = 'decimal';
  field.autocomplete = 'off';
  field.size = 7;
  label.append(field, element('span', 'oceano-lesson-exercise-unit', exercise.unit));
  const check = element('button', 'oceano-lesson-exercise-check', WORDS.check[language]);
  check.type = 'submit';
  form.append(label, check);
  const result = element('p', 'oceano-lesson-exercise-result');
  result.setAttribute('aria-live', 'polite');
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    const now = params();
    const typed = parseTyped(field.value);
    result.replaceChildren();
    delete result.dataset.verdict;
    if (!now) return;
    if (!Number.isFinite(typed)) {
      result.textContent = WORDS.empty[language];
      return;
    }
    const at = moment();
    const expected = exercise.expected(now, at);
    if (!Number.isFinite(expected)) {
      result.textContent = WORDS.noTheory[language];
      return;
    }
    const ok = withinTolerance(typed, expected, exercise.tolerance);
    result.dataset.verdict = ok ? 'within' : 'not-yet';
    // Spanish writes the decimal comma, as the rest of the page does (19,47°).
    const number = (value: number, digits: number) => (language === 'es' ? value.toFixed(digits).replace('.', ',') : value.toFixed(digits));
    const off = number(100 * (typed / expected - 1), 1);
    result.append(
      element('strong', 'oceano-lesson-exercise-verdict', ok ? WORDS.within[language] : WORDS.notYet[language]),
      ` (${off.startsWith('-') ? '' : '+'}${off} %). `,
      `${WORDS.theory[language]}: ${exercise.symbol} = ${number(expected, 2)} ${exercise.unit}; ${theoryLine(exercise, now, at, language)}.`,
    );
  });
  root.append(heading, task, tolerance, form, result);
  return root;
}
