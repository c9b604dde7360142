import { paramDefs, type OceanParams } from '../sim/params/params';
import { formatCameraText } from '../app/camera/cameraPose';
import type { Lesson } from '../app/lessons/lessonCatalog';

/**
 * The attributes that make an <oceano-view> show a lesson's view without opening its card
 * (the page's caption is the card): its preset first (stones and culling camera come with
 * it), then the lesson's own parameters and camera, exactly as lessonView() layers them.
 */
export function lessonViewAttributes(lesson: Lesson): [string, string][] {
  const attributes: [string, string][] = [];
  if (lesson.preset) attributes.push(['preset', lesson.preset]);
  for (const [key, value] of Object.entries(lesson.params ?? {}) as [keyof OceanParams, unknown][]) {
    const kind = paramDefs[key].kind;
    attributes.push([key, kind === 'boolean' ? (value ? '1' : '0') : kind === 'color' ? String(value).replace(/^#/, '') : String(value)]);
  }
  if (lesson.camera) attributes.push(['cam', formatCameraText(lesson.camera)]);
  return attributes;
}

/** Where the build puts a lesson's poster (scripts/build/posters.ts), from the course page. */
export const lessonPoster = (id: string): string => `../posters/lessons/${id}.webp`;
