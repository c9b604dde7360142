import { headlineMark, type Diagram, type DiagramMark } from '../../../sim/teaching/diagrams/diagram';
import type { Language } from '../../language/i18n';
import { DIAGRAM_WORDS, type MarkWords } from './diagramWords';

/** A mark's label in `language`, its value written as that language writes numbers (48,6 in Spanish). */
export function markLabel(diagram: Diagram, mark: DiagramMark, language: Language): string {
  const words = DIAGRAM_WORDS[diagram.kind].marks[mark.id];
  if (!words) throw new Error(`No words for mark ${diagram.kind}.${mark.id}.`);
  return filled(words, mark, language);
}

function filled(words: MarkWords, mark: DiagramMark, language: Language): string {
  const value = new Intl.NumberFormat(language, {
    minimumFractionDigits: words.digits,
    maximumFractionDigits: words.digits,
    useGrouping: false,
  }).format(mark.value);
  return words[language].replaceAll('{v}', value).replace('{i}', String((mark.index ?? 0) + (words.first ?? 0)));
}

/** The diagram's accessible name: what it is and its key value ("Snell’s window seen from below: critical angle 48.6°"). */
export function diagramName(diagram: Diagram, language: Language): string {
  const words = DIAGRAM_WORDS[diagram.kind];
  const mark = headlineMark(diagram);
  const own = words.headline?.[mark.id];
  return `${words.name[language]}: ${own ? filled(own, mark, language) : markLabel(diagram, mark, language)}`;
}

/** Every labelled value of the diagram, for its longer description. */
export function diagramDescription(diagram: Diagram, language: Language): string {
  return diagram.marks
    .filter((m) => !m.quiet)
    .map((m) => markLabel(diagram, m, language))
    .join('; ');
}
