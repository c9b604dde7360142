import { message } from '../../sim/params/message';
import { isParamKey, paramKeys } from '../../sim/params/params';
import { createAutomationApi, createFailedApi, type OceanoApi } from '../api/automationApi';
import { hasWebGL2, prefersReducedMotion, showFatal, startApp, watchActivity } from '../boot/bootSupport';
import { preferredLanguage, Translator } from '../language/i18n';
import { DEFAULT_BOAT_MODEL, OceanApp } from '../oceanApp';
import { DEFAULT_CAMERA } from '../camera/cameraPose';
import { PAGE_KEYS, parseSettings } from '../url/urlState';

/** HTML lower-cases attribute names: map them back to the URL's names (swellamplitude → swellAmplitude). */
const SETTING_NAMES = new Map<string, string>([...paramKeys, ...PAGE_KEYS].map((name) => [name.toLowerCase(), name]));

/** Attributes that do not configure the ocean. */
const HTML_ATTRIBUTES = new Set(['id', 'class', 'style', 'title', 'hidden', 'tabindex', 'slot', 'part', 'role', 'dir']);

/**
 * `<oceano-view seed="3" t="10" cam="0,9,40,0,0,-60"></oceano-view>`: one live ocean figure
 * in a course page. Its attributes are the URL parameters, validated the same way; several
 * can share a page because each owns its app, canvas and WebGL context, exposed as
 * `element.oceano`.
 */
export class OceanoViewElement extends HTMLElement {
  /** The directory of dist/oceano.js: the built-in sky and the full page (for share links) sit beside it. */
  static assetBase = '';

  /** Parameters, time, camera and lesson follow their attributes while the element lives; the rest is read once, when it is connected. */
  static get observedAttributes(): string[] {
    return [...paramKeys.map((key) => key.toLowerCase()), 't', 'cam', 'lesson'];
  }

  oceano: OceanoApi | null = null;
  private app: OceanApp | null = null;
  private stopWatching: (() => void) | null = null;

  connectedCallback(): void {
    if (this.app) return;
    const state = parseSettings(this.settings());
    const language = state.language ?? preferredLanguage(navigator.languages);
    const tr = new Translator(language);
    if (!hasWebGL2()) {
      const text = tr.message(message('webgl2Missing'));
      showFatal(this, text);
      this.oceano = createFailedApi(new Error(text));
      return;
    }
    const assets = OceanoViewElement.assetBase || document.baseURI;
    const skyBase = new URL(state.sky ?? 'sky/', state.sky === null ? assets : document.baseURI).href;
    const boatUrl = new URL(state.boat ?? DEFAULT_BOAT_MODEL, state.boat === null ? assets : document.baseURI).href;
    const app = new OceanApp(this, {
      state,
      language,
      reducedMotion: prefersReducedMotion(),
      skyBase,
      boatUrl,
      shareBase: new URL('index.html', assets).href,
      showPanel: false,
    });
    this.app = app;
    const ready = startApp(app, this, tr);
    this.oceano = createAutomationApi(app, ready);
    this.stopWatching = watchActivity(app, this);
    ready.then(
      () => this.dispatchEvent(new CustomEvent('ready')),
      () => undefined,
    );
  }

  attributeChangedCallback(name: string, _old: string | null, text: string | null): void {
    const app = this.app;
    if (!app || !app.isStarted() || text === null) return;
    const key = SETTING_NAMES.get(name) ?? name;
    // A lesson sets a whole view, and an unknown one says so and changes nothing.
    if (key === 'lesson') return void app.openLesson(text);
    // Validated exactly as at start-up, with the same notice and the same fallback.
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
    this.stopWatching?.();
    this.stopWatching = null;
    this.app?.dispose();
    this.app = null;
    this.oceano = null;
    this.replaceChildren();
  }

  /** The element's attributes as URL-style name/value pairs, ordinary HTML attributes left out. */
  private settings(): [string, string][] {
    const pairs: [string, string][] = [];
    for (const attribute of Array.from(this.attributes)) {
      const name = attribute.name.toLowerCase();
      if (HTML_ATTRIBUTES.has(name) || name.startsWith('data-') || name.startsWith('aria-')) continue;
      pairs.push([SETTING_NAMES.get(name) ?? attribute.name, attribute.value]);
    }
    return pairs;
  }
}
