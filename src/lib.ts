import widgetStyles from './app/panel/widgets.css?inline';
import { OceanoViewElement } from './app/element/oceanoViewElement';

/**
 * The library build (dist/oceano.js): registers <oceano-view>. The sky images are looked
 * up beside this script, so dist/ works when copied anywhere; the path is a variable so
 * Vite leaves the URL to be resolved at run time.
 */
const scriptDirectory = './';
OceanoViewElement.assetBase = new URL(scriptDirectory, import.meta.url).href;

/** The styles go in as a constructed sheet: no <style> element, so a strict CSP needs no 'unsafe-inline'. */
function adoptStyles(): void {
  const sheet = new CSSStyleSheet();
  sheet.replaceSync(widgetStyles);
  document.adoptedStyleSheets = [...document.adoptedStyleSheets, sheet];
}

if (!customElements.get('oceano-view')) {
  adoptStyles();
  customElements.define('oceano-view', OceanoViewElement);
}

export { OceanoViewElement };
export type { OceanoApi } from './app/api/automationApi';
