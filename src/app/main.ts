import './style.css';
import './widgets.css';
import { message } from '../sim/message';
import { DEFAULT_BOAT_MODEL, OceanApp } from './oceanApp';
import { createAutomationApi } from './automationApi';
import { hasWebGL2, prefersReducedMotion, showFatal, startApp, watchActivity } from './bootSupport';
import { preferredLanguage, Translator } from './i18n';
import { parseUrlState } from './urlState';

/** The page bootstrap: reads the URL and the browser's preferences and hands them to one OceanApp. */
function boot(): void {
  const container = document.getElementById('oceano') as HTMLElement;
  const state = parseUrlState(window.location.search);
  const language = state.language ?? preferredLanguage(navigator.languages);
  const tr = new Translator(language);
  document.documentElement.lang = language;
  if (!hasWebGL2()) {
    showFatal(container, tr.message(message('webgl2Missing')));
    return;
  }
  if (state.embed) document.documentElement.classList.add('oceano-embedded');
  const app = new OceanApp(container, {
    state,
    language,
    reducedMotion: prefersReducedMotion(),
    skyBase: state.sky ?? 'sky',
    boatUrl: state.boat ?? DEFAULT_BOAT_MODEL,
    shareBase: `${window.location.origin}${window.location.pathname}`,
    showPanel: !state.embed,
  });
  const ready = startApp(app, container, tr);
  // In an iframe the implicit root is the top page's viewport: an embed scrolled away stops drawing.
  watchActivity(app, container);
  window.oceano = createAutomationApi(app, ready);
}

boot();
