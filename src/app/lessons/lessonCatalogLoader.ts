import type * as catalogModule from './lessonCatalog';

/**
 * What reading a lesson needs of the catalog: its ids, a lookup and the view one opens. The catalog
 * is fetched only when a lesson is asked for (?lesson=, the drawer, setLesson): the page's first
 * script stays without it.
 */
export type LessonCatalog = Pick<typeof catalogModule, 'findLesson' | 'lessonIds' | 'lessonView'>;

let loaded: LessonCatalog | null = null;

/** The catalog, once loadLessonCatalog has brought it; null before. */
export const loadedLessonCatalog = (): LessonCatalog | null => loaded;

export function loadLessonCatalog(): Promise<LessonCatalog> {
  return import('./lessonCatalog').then((catalog) => (loaded = catalog));
}
