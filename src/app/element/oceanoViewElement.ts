import { message, type Message } from '../../sim/params/message';
import { isParamKey, paramDefs, paramKeys } from '../../sim/params/params';
import { createAutomationApi, createFailedApi, type OceanoApi } from '../api/automationApi';
import { hasWebGL2, prefersReducedMotion, showFatal, startApp, watchActivity } from '../boot/bootSupport';
import { canvasLabel, preferredLanguage, Translator } from '../language/i18n';
import { DEFAULT_BOAT_MODEL, OceanApp } from '../oceanApp';
import { DEFAULT_CAMERA } from '../camera/cameraPose';
import { PAGE_KEYS, parseSettings, type UrlState } from '../url/urlState';
// A figure's `lesson` attribute is read as it starts: the element's script carries the catalog.
import * as lessons from '../lessons/lessonCatalog';
import { readStartupOptions, STARTUP_ATTRIBUTES, type StartupOptions } from './startupOptions';
import { FigureCover } from './figureCover';
import { gateTouchOrbit } from './touchOrbitGate';
import { ContextBudget, distanceToViewport, type BudgetedFigure } from './contextBudget';

/** HTML lower-cases attribute names: map them back to the URL's names (swellamplitude → swellAmplitude). */
/** An attribute's name for a setting: its name lower-cased (HTML folds case), or written kebab-case (interactive-waves). */
const kebab = (name: string) => name.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`);
const SETTING_NAMES = new Map<string, string>(
  [...paramKeys, ...PAGE_KEYS].flatMap(
    (name) =>
      [
        [name.toLowerCase(), name],
        [kebab(name), name],
      ] as [string, string][],
  ),
);
/** A boolean written bare (<oceano-view interactive-waves>) is on, as HTML's own are. */
const settingText = (key: string, text: string) => (text === '' && isParamKey(key) && paramDefs[key].kind === 'boolean' ? '1' : text);

/** Attributes that do not configure the ocean. */
const HTML_ATTRIBUTES = new Set<string>([
  'id',
  'class',
  'style',
  'title',
  'hidden',
  'tabindex',
  'slot',
  'part',
  'role',
  'dir',
  ...STARTUP_ATTRIBUTES,
]);

/**
 * waiting: no context yet (lazy, or a poster until activated); starting; live; released: its
 * context given back, a still of its last frame in place, its state kept to start again.
 */
type Phase = 'detached' | 'waiting' | 'starting' | 'live' | 'released' | 'failed';

/**
 * What a released figure keeps to come back as it was: its share link's settings, as the
 * link's query text (one string, where name/value pairs made a few kilobytes of small arrays
 * per figure), and whether time ran.
 */
interface SavedView {
  query: string;
  playing: boolean;
}

/**
 * `<oceano-view seed="3" t="10" cam="0,9,40,0,0,-60"></oceano-view>`: one live ocean figure
 * in a course page. Its attributes are the URL parameters, validated the same way, plus
 * model-viewer's start-up attributes (loading, reveal, poster, alt). A page may hold many:
 * a figure starts when it comes near the screen and, far from it, gives its WebGL context
 * back and keeps a still of its last frame, so only the figures near the screen hold one.
 * Events: `progress` (detail.totalProgress), `load` (first frame), `ready` (boat in the
 * picture), `error` (detail.type, detail.message).
 */
export class OceanoViewElement extends HTMLElement implements BudgetedFigure {
  /** The directory of dist/oceano.js: the built-in sky and the full page (for share links) sit beside it. */
  static assetBase = '';
  /**
   * How far from the viewport a figure starts, and beyond which it gives its context back
   * (an IntersectionObserver rootMargin: half a screen above and below).
   */
  static nearMargin = '50% 0px';
  /** The page's WebGL contexts for figures, well under Chromium's 16 so the page keeps some of its own. */
  static readonly contexts = new ContextBudget(12);
  /** false: figures keep their context wherever they are (a page of a few figures that never want a restart). */
  static releaseContexts = true;
  /** Whether this browser has WebGL2, asked once per page: each probe makes and drops a context. */
  private static webgl2: boolean | null = null;

  /** Parameters, time, camera and lesson follow their attributes while the element lives; the rest is read once, when it is connected. */
  static get observedAttributes(): string[] {
    return [...paramKeys.flatMap((key) => [key.toLowerCase(), kebab(key)]), 't', 'cam', 'lesson'];
  }

  /** The automation API of the live ocean; null while the figure waits, starts or is released. */
  oceano: OceanoApi | null = null;
  private app: OceanApp | null = null;
  private phase: Phase = 'detached';
  private startup!: StartupOptions;
  /** What was wrong with the start-up attributes: said by the figure's notices once it starts. */
  private startupNotices: Message[] = [];
  private tr!: Translator;
  private cover: FigureCover | null = null;
  private activated = false;
  private near = false;
  private releaseWhenStarted = false;
  private saved: SavedView | null = null;
  /** Attribute changes made while starting or released, applied once live. */
  private pendingChanges: [string, string][] = [];
  private loadFired = false;
  /** Counts the apps this element has made: hooks of one that has been closed since are ignored. */
  private generation = 0;
  private stopWatching: (() => void) | null = null;
  private stopGatingTouch: (() => void) | null = null;
  private nearWatch: IntersectionObserver | null = null;

  connectedCallback(): void {
    if (this.phase !== 'detached') return;
    const state = parseSettings(this.settings(), lessons);
    const { options, notices } = readStartupOptions(this);
    this.startup = options;
    this.startupNotices = notices;
    this.tr = new Translator(state.language ?? preferredLanguage(navigator.languages));
    this.phase = 'waiting';
    this.cover = new FigureCover(this, options.alt ?? canvasLabel(this.tr, state.params));
    if (options.poster) this.cover.showPoster(new URL(options.poster, document.baseURI).href);
    this.activated = options.reveal === 'auto';
    if (!this.activated) this.cover.showRevealButton(this.tr.ui('play'), () => ((this.activated = true), this.reconcile()));
    this.addEventListener('webglcontextlost', this.onContextLost, true);
    for (const notice of notices) this.reportError('attribute', notice);
    if (typeof IntersectionObserver === 'function') {
      this.nearWatch = new IntersectionObserver(
        (entries) => {
          this.near = entries[entries.length - 1].isIntersecting;
          this.reconcile();
        },
        { rootMargin: OceanoViewElement.nearMargin },
      );
      this.nearWatch.observe(this);
    } else {
      this.near = true;
    }
    this.reconcile();
  }

  attributeChangedCallback(name: string, _old: string | null, text: string | null): void {
    if (text === null) return;
    const key = SETTING_NAMES.get(name) ?? name;
    if (this.phase === 'live' && this.app) this.applySetting(this.app, key, settingText(key, text));
    // Not live yet, or released: applied when it is (a waiting figure reads its attributes when it starts).
    else if (this.phase === 'starting' || this.phase === 'released') this.pendingChanges.push([key, settingText(key, text)]);
  }

  /** Validated exactly as at start-up, with the same notice and the same fallback. */
  private applySetting(app: OceanApp, key: string, text: string): void {
    // A lesson sets a whole view, and an unknown one says so and changes nothing.
    if (key === 'lesson') return void app.openLesson(text);
    const state = parseSettings([[key, text]]);
    for (const notice of state.notices) app.notify(notice);
    if (isParamKey(key)) {
      app.setParams({ [key]: state.params[key] });
    } else if (key === 't') {
      app.setTime(state.time ?? 0);
      if (state.time === null) app.play();
      else app.pause();
    } else if (key === 'cam') {
      app.setCamera(state.camera ?? DEFAULT_CAMERA);
    }
  }

  disconnectedCallback(): void {
    this.nearWatch?.disconnect();
    this.nearWatch = null;
    this.removeEventListener('webglcontextlost', this.onContextLost, true);
    this.closeApp();
    OceanoViewElement.contexts.free(this);
    this.cover?.dispose();
    this.cover = null;
    this.saved = null;
    this.pendingChanges = [];
    this.phase = 'detached';
    this.replaceChildren();
  }

  distanceToViewport(): number {
    return distanceToViewport(this);
  }

  releaseForBudget(): void {
    if (this.phase === 'live') this.release();
    else if (this.phase === 'starting') this.releaseWhenStarted = true;
  }

  retry(): void {
    this.reconcile();
  }

  /** Starts, or gives back the context, to match where the figure is and what the reader did. */
  private reconcile(): void {
    const wanted = this.activated && (this.near || (this.startup.loading === 'eager' && this.phase === 'waiting'));
    const releasing = OceanoViewElement.releaseContexts;
    if (wanted && (this.phase === 'waiting' || this.phase === 'released')) {
      if (!releasing || OceanoViewElement.contexts.claim(this)) this.start();
    } else if (wanted && this.phase === 'starting') {
      this.releaseWhenStarted = false;
    } else if (!wanted && releasing) {
      if (this.phase === 'live') this.release();
      else if (this.phase === 'starting') this.releaseWhenStarted = true;
      else OceanoViewElement.contexts.free(this);
    }
  }

  private start(): void {
    const saved = this.saved;
    const state = parseSettings(saved ? [...new URLSearchParams(saved.query), ...this.pendingChanges] : this.settings(), lessons);
    const firstStart = saved === null;
    this.pendingChanges = [];
    this.phase = 'starting';
    this.releaseWhenStarted = false;
    if (!(OceanoViewElement.webgl2 ??= hasWebGL2())) {
      this.fail('webgl', message('webgl2Missing'));
      return;
    }
    const generation = ++this.generation;
    const app = this.createApp(state, generation, firstStart);
    // Focusable, so a reader can orbit it from the keyboard (J/L, I/K, U/O): the keys go to the figure that has the focus.
    app.canvas.tabIndex = 0;
    if (saved?.playing) app.play();
    if (firstStart) {
      for (const notice of this.startupNotices) app.notify(notice);
      for (const notice of state.notices) this.reportError('attribute', notice);
    }
    this.app = app;
    const ready = startApp(app, this, this.tr);
    this.oceano = createAutomationApi(app, ready);
    this.stopWatching = watchActivity(app, this);
    ready.then(
      () => {
        if (this.generation !== generation) return;
        // The poster or the still gives way once the picture is complete: a first frame may still
        // lack the boat or a view whose code comes after it (the heightmaps, the underwater passes).
        this.cover?.uncover();
        this.phase = 'live';
        this.saved = null;
        for (const [key, text] of this.pendingChanges.splice(0)) this.applySetting(app, key, text);
        if (firstStart) this.dispatchEvent(new CustomEvent('ready'));
        if (this.releaseWhenStarted) this.release();
        else this.reconcile();
      },
      (error: unknown) => {
        if (this.generation !== generation) return;
        this.cover?.uncover();
        this.phase = 'failed';
        OceanoViewElement.contexts.free(this);
        this.dispatchError('start', error instanceof Error ? error.message : String(error));
      },
    );
  }

  private createApp(state: UrlState, generation: number, firstStart: boolean): OceanApp {
    const assets = OceanoViewElement.assetBase || document.baseURI;
    const current = () => this.generation === generation;
    return new OceanApp(this, {
      state,
      language: this.tr.language,
      reducedMotion: prefersReducedMotion(),
      skyBase: new URL(state.sky ?? 'sky/', state.sky === null ? assets : document.baseURI).href,
      boatUrl: new URL(state.boat ?? DEFAULT_BOAT_MODEL, state.boat === null ? assets : document.baseURI).href,
      shareBase: new URL('index.html', assets).href,
      showPanel: false,
      alt: this.startup.alt ?? undefined,
      onProgress: (fraction) => {
        if (current() && firstStart) this.dispatchEvent(new CustomEvent('progress', { detail: { totalProgress: fraction } }));
      },
      onFirstFrame: () => {
        if (!current() || !this.app) return;
        const app = this.app;
        void app.orbit.loaded.then((controls) => {
          if (controls && this.app === app) this.stopGatingTouch = gateTouchOrbit(controls, app.canvas);
        });
        if (this.loadFired) return;
        this.loadFired = true;
        this.dispatchEvent(new CustomEvent('load'));
      },
    });
  }

  /** Keeps a still of the last frame and everything needed to come back, then gives the GPU side and the context back. */
  private release(): void {
    const app = this.app;
    if (!app) return;
    const share = new URL(app.shareUrl());
    // A preset's culling camera is not in the share link (the lesson is): the preset comes first, the link's values over it.
    const query = new URLSearchParams(this.settings().filter(([key]) => key === 'preset'));
    for (const [key, value] of share.searchParams) query.append(key, value);
    this.saved = { query: query.toString(), playing: app.clock.playing };
    this.pendingChanges = [];
    app.renderFrame(false);
    this.cover?.showStill(app.canvas);
    this.closeApp();
    this.phase = 'released';
    OceanoViewElement.contexts.free(this);
  }

  private closeApp(): void {
    const app = this.app;
    // Cleared first: the context loss that dispose causes is ours, not the browser's.
    this.app = null;
    this.generation++;
    this.oceano = null;
    this.stopWatching?.();
    this.stopWatching = null;
    this.stopGatingTouch?.();
    this.stopGatingTouch = null;
    app?.dispose();
  }

  /** A context the browser took away (too many on the page, a GPU reset): the notice shows, and the page hears of it. */
  private readonly onContextLost = (event: Event): void => {
    if (this.app && event.target === this.app.canvas) this.reportError('contextlost', message('contextLost'));
  };

  private fail(type: string, reason: Message): void {
    const text = this.tr.message(reason);
    this.phase = 'failed';
    OceanoViewElement.contexts.free(this);
    this.cover?.dispose();
    showFatal(this, text);
    this.oceano = createFailedApi(new Error(text));
    this.dispatchError(type, text);
  }

  private reportError(type: string, reason: Message): void {
    this.dispatchError(type, this.tr.message(reason));
  }

  private dispatchError(type: string, text: string): void {
    this.dispatchEvent(new CustomEvent('error', { detail: { type, message: text } }));
  }

  /** The element's attributes as URL-style name/value pairs, ordinary HTML attributes left out. */
  private settings(): [string, string][] {
    const pairs: [string, string][] = [];
    for (const attribute of Array.from(this.attributes)) {
      const name = attribute.name.toLowerCase();
      if (HTML_ATTRIBUTES.has(name) || name.startsWith('data-') || name.startsWith('aria-')) continue;
      const key = SETTING_NAMES.get(name) ?? attribute.name;
      pairs.push([key, settingText(key, attribute.value)]);
    }
    return pairs;
  }
}
