import type { OceanParams } from '../../../sim/params/params';
import { LESSON_DIAGRAMS, MOVING_DIAGRAMS } from '../../../sim/teaching/diagrams/lessonDiagrams';
import type { Language } from '../../language/i18n';
import { DiagramSvg } from './diagramSvg';

/** A moving diagram is redrawn at most this often, seconds of the clock: the eye needs no more. */
const REDRAW_EVERY = 0.1;

export interface LessonDiagram {
  element: HTMLElement;
  /** Redraws from `params` at the clock's `time` (s); a still diagram only when the parameters change. */
  update(params: OceanParams, time: number): void;
}

/** The flat diagram a lesson's card shows beside the sea, or null where it has none. */
export function lessonDiagram(lessonId: string, language: Language = 'en'): LessonDiagram | null {
  const draw = LESSON_DIAGRAMS[lessonId];
  if (!draw) return null;
  const view = new DiagramSvg(language);
  const moving = MOVING_DIAGRAMS.has(lessonId);
  let opened: number | null = null;
  let drawnParams: OceanParams | null = null;
  let drawnTime = Number.NEGATIVE_INFINITY;
  return {
    element: view.element,
    update(params, time) {
      opened ??= time;
      if (params === drawnParams && (!moving || Math.abs(time - drawnTime) < REDRAW_EVERY)) return;
      drawnParams = params;
      drawnTime = time;
      view.render(draw(params, time - opened, time));
    },
  };
}
