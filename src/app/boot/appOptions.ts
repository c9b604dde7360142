import type { Language } from '../language/i18n';
import type { UrlState } from '../url/urlState';

/** What the app is told by its bootstrap (main.ts or <oceano-view>): it reads no URL, attribute or media query itself. */
export interface OceanAppOptions {
  /** Validated settings from the URL or the element's attributes. */
  state: UrlState;
  language: Language;
  /** prefers-reduced-motion: start paused, with the play button showing. */
  reducedMotion: boolean;
  /** Directory holding the six sky images, as a URL or a path relative to the document. */
  skyBase: string;
  /** The boat's glTF, as a URL or a path relative to the document. */
  boatUrl: string;
  /** The link a shared view starts with (page address without its query). */
  shareBase: string;
  /** The lil-gui panel; off when embedded. */
  showPanel: boolean;
  /** The canvas's accessible name in place of the one that says what it shows (an element's alt). */
  alt?: string;
  /** Hears the loading steps as a fraction done, 0 to 1 (an element's progress events). */
  onProgress?: (fraction: number) => void;
  /** Called once the first frame is drawn (an element's load event). */
  onFirstFrame?: () => void;
}
