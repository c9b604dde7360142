import type { Language } from '../language/i18n';
import type { OceanParams } from '../../sim/params/params';
import { exerciseFor, withinTolerance, type ExerciseQuantity, type MeasurementExercise } from '../../sim/teaching/measurementExercises';

type Words = Record<Language, string>;

/** What the student is asked to do, by quantity: which tool, where to read it. */
const TASKS: Record<ExerciseQuantity, Words> = {
  significantHeight: {
    en: 'Open the physics panel (Physics panel in the controls) and read the significant wave height Hs = 4σ(η) it measured on this sea, in the “measured” column. Type it here.',
    es: 'Abre el panel de física (Physics panel en los controles) y lee la altura significativa Hs = 4σ(η) que midió en este mar, en la columna “measured”. Escríbela aquí.',
  },
  peakPeriod: {
    en: 'Open the physics panel (Physics panel in the controls) and read the peak period Tp it measured on this sea, in the “measured” column. Type it here.',
    es: 'Abre el panel de física (Physics panel en los controles) y lee el período de pico Tp que midió en este mar, en la columna “measured”. Escríbelo aquí.',
  },
  transverseWavelength: {
    en: 'Pause, open the sea tools (Sea tools in the panel), choose the ruler and lay it along the boat’s track behind it, from one transverse crest to a crest a few waves further. Divide by the number of waves and type the wavelength λ.',
    es: 'Pausa, abre las herramientas del mar (Sea tools en el panel), elige la regla y tiéndela sobre la estela detrás del barco, de una cresta transversal a otra unas olas más allá. Divide por el número de olas y escribe la longitud de onda λ.',
  },
};

/** How the theory follows, with the live values filled in. */
function theoryLine(exercise: MeasurementExercise, params: OceanParams, language: Language): string {
  const es = language === 'es';
  switch (exercise.quantity) {
    case 'significantHeight':
      return es
        ? `Hs = 4√m₀, con m₀ = ∫S(ω)dω del espectro ${params.spectrum} a U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` y ${params.fetch} km de fetch` : ''}`
        : `Hs = 4√m₀, m₀ = ∫S(ω)dω of the ${params.spectrum} spectrum at U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` over a ${params.fetch} km fetch` : ''}`;
    case 'peakPeriod':
      return es
        ? `Tp = 2π/ωp, ωp el pico del espectro ${params.spectrum} a U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` y ${params.fetch} km de fetch` : ''}`
        : `Tp = 2π/ωp, ωp the peak of the ${params.spectrum} spectrum at U₁₀ = ${params.windSpeed} m/s${params.spectrum === 'jonswap' ? ` over a ${params.fetch} km fetch` : ''}`;
    case 'transverseWavelength':
      return es
        ? `las olas transversales acompañan al barco: c = √(g/k) = U, k = g/U², λ = 2πU²/g con U = ${params.boatSpeed} m/s`
        : `the transverse waves keep pace with the boat: c = √(g/k) = U, so k = g/U², λ = 2πU²/g with U = ${params.boatSpeed} m/s`;
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
 * the moment (`params()`) and how it follows.
 */
export function lessonExercise(lesson: string, language: Language, params: () => OceanParams | null): HTMLElement | null {
  const exercise = exerciseFor(lesson);
  if (!exercise) return null;
  const root = element('section', 'oceano-lesson-exercise');
  root.dataset.exercise = exercise.quantity;
  const headingId = `oceano-exercise-${Math.random().toString(36).slice(2)}`;
  const heading = element('h3', 'oceano-lesson-exercise-title', WORDS.heading[language]);
  heading.id = headingId;
  root.setAttribute('aria-labelledby', headingId);
  const task = element('p', 'oceano-lesson-exercise-task', TASKS[exercise.quantity][language]);
  const tolerance = element('p', 'oceano-lesson-exercise-tolerance', `${WORDS.tolerance[language]}: ±${Math.round(exercise.tolerance * 100)} %`);
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
    const expected = exercise.expected(now);
    const ok = withinTolerance(typed, expected, exercise.tolerance);
    result.dataset.verdict = ok ? 'within' : 'not-yet';
    // Spanish writes the decimal comma, as the rest of the page does (19,47°).
    const number = (value: number, digits: number) => (language === 'es' ? value.toFixed(digits).replace('.', ',') : value.toFixed(digits));
    const off = number(100 * (typed / expected - 1), 1);
    result.append(
      element('strong', 'oceano-lesson-exercise-verdict', ok ? WORDS.within[language] : WORDS.notYet[language]),
      ` (${off.startsWith('-') ? '' : '+'}${off} %). `,
      `${WORDS.theory[language]}: ${exercise.symbol} = ${number(expected, 2)} ${exercise.unit}; ${theoryLine(exercise, now, language)}.`,
    );
  });
  root.append(heading, task, tolerance, form, result);
  return root;
}
