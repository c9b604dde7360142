import widgetStyles from './app/panel/widgets.css?inline';
import { OceanoViewElement } from './app/element/oceanoViewElement';

/**
 * The element's entry (dist/oceano.js in the app's build, dist/element/oceano-view.js in the
 * package's): registers <oceano-view>. The sky and the boat are looked up beside this script,
 * so it works when copied anywhere; the path is a variable so Vite leaves the URL to be
 * resolved at run time.
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
