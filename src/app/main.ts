// lil-gui's styles as a stylesheet of the page, not a <style> it injects (see vite.config.ts, lilGuiFontFile);
// by path, because the package's exports name no stylesheet.
import '../../node_modules/lil-gui/dist/lil-gui.css';
import './style.css';
import './panel/widgets.css';
import { message } from '../sim/params/message';
import { DEFAULT_BOAT_MODEL, OceanApp } from './oceanApp';
import { createAutomationApi, createFailedApi } from './api/automationApi';
import { hasWebGL2, prefersReducedMotion, showFatal, startApp, watchActivity } from './boot/bootSupport';
import { preferredLanguage, Translator } from './language/i18n';
import { parseUrlState } from './url/urlState';
import { loadLessonCatalog, type LessonCatalog } from './lessons/lessonCatalogLoader';

/** The page bootstrap: reads the URL and the browser's preferences and hands them to one OceanApp. */
function boot(lessons: LessonCatalog | null): void {
  const container = document.getElementById('oceano-page') as HTMLElement;
  const state = parseUrlState(window.location.search, lessons);
  const language = state.language ?? preferredLanguage(navigator.languages);
  const tr = new Translator(language);
  document.documentElement.lang = language;
  if (!hasWebGL2()) {
    const text = tr.message(message('webgl2Missing'));
    showFatal(container, text);
    window.oceano = createFailedApi(new Error(text));
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

function bootOrFail(lessons: LessonCatalog | null): void {
  try {
    boot(lessons);
  } catch (error) {
    // Whatever stopped the boot, `oceano.ready` says it rather than never settling.
    window.oceano = createFailedApi(error instanceof Error ? error : new Error(String(error)));
    throw error;
  }
}

performance.mark('oceano:script');
// Only a page that names a lesson waits for the lessons' catalog before it reads its URL.
if (new URLSearchParams(window.location.search).has('lesson')) {
  loadLessonCatalog().then(bootOrFail, (error: unknown) => {
    window.oceano = createFailedApi(error instanceof Error ? error : new Error(String(error)));
  });
} else {
  bootOrFail(null);
}
