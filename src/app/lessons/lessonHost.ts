import type { OceanParams } from '../../sim/params/params';
import type { Translator } from '../language/i18n';
import type { LessonHooks } from './lessonHooks';
import type { LessonDrawer } from './lessonDrawer';
import type { lessonList } from './lessonOutline';

/**
 * The lessons beside one ocean: which is open, and the drawer that shows them. The drawer's
 * code, words and quotes are a chunk of their own, fetched after the first frame, so the
 * sea does not wait for them. The full page lists every lesson; an embedded figure shows
 * only the card of the lesson it was given.
 */
export class LessonHost {
  private drawer?: LessonDrawer;
  private drawerLoad?: Promise<void>;
  private titlesLoad?: Promise<void>;
  private list?: typeof lessonList;
  private shown: OceanParams;
  private disposed = false;
  current: string | null = null;

  constructor(
    private readonly container: HTMLElement,
    private readonly tr: Translator,
    private readonly listed: boolean,
    params: OceanParams,
    private readonly hooks: LessonHooks,
  ) {
    this.shown = params;
  }

  /** Marks `id` open (its view is already set) and shows its card. */
  show(id: string): Promise<void> {
    this.current = id;
    this.drawer?.show(id);
    return this.load();
  }

  /**
   * Fetches the lessons' titles (what oceano.lessons() answers), and the drawer where there
   * is something to show; a failed fetch leaves the sea as it is.
   */
  load(): Promise<void> {
    this.titlesLoad ??= import('./lessonOutline').then(
      (titles) => void (this.list = titles.lessonList),
      (error: unknown) => console.warn('Oceano: the lessons could not be loaded.', error),
    );
    if (!this.listed && this.current === null) return this.titlesLoad;
    this.drawerLoad ??= import('./lessonDrawer').then(
      ({ LessonDrawer }) => {
        if (this.disposed) return;
        this.drawer = new LessonDrawer(this.container, this.tr, this.listed, this.hooks);
        this.drawer.sync(this.shown);
        if (this.current !== null) this.drawer.show(this.current);
      },
      (error: unknown) => console.warn('Oceano: the lessons could not be loaded.', error),
    );
    return Promise.all([this.titlesLoad, this.drawerLoad]).then(() => undefined);
  }

  /** The lessons in order, titled in the page's language; their titles arrive with `ready`. */
  titles(): ReturnType<typeof lessonList> {
    if (!this.list) throw new Error("The lessons' titles have not arrived yet: await oceano.ready first.");
    return this.list(this.tr.language);
  }

  sync(params: OceanParams): void {
    this.shown = params;
    this.drawer?.sync(params);
  }

  /** After each drawn frame: labels that follow the sea (the wake guide's angle, Snell's window) move with the camera. */
  afterFrame(): void {
    this.drawer?.placeLabels();
  }

  dispose(): void {
    this.disposed = true;
    this.drawer?.dispose();
  }
}
