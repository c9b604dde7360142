import { message, type Message } from '../../sim/params/message';

/** How an <oceano-view> starts and presents itself: attributes read once, when it is connected. */
export interface StartupOptions {
  /** lazy: start when the figure comes near the viewport; eager: start at once. */
  loading: 'lazy' | 'eager';
  /** auto: start by itself (per `loading`); interaction: stay a poster until the reader starts it. */
  reveal: 'auto' | 'interaction';
  /** An image shown until the first frame is drawn. */
  poster: string | null;
  /** The figure's accessible name. */
  alt: string | null;
}

/** Attributes of the element itself, not settings of the ocean. */
export const STARTUP_ATTRIBUTES = ['loading', 'reveal', 'poster', 'alt'] as const;

const LOADING = ['lazy', 'eager', 'auto'] as const;
const REVEAL = ['auto', 'interaction'] as const;

/** Reads the start-up attributes; a value it does not know falls back to the default, with a message saying so. */
export function readStartupOptions(element: Element): { options: StartupOptions; notices: Message[] } {
  const notices: Message[] = [];
  const choose = <T extends string>(name: string, allowed: readonly T[], fallback: T): T => {
    const text = element.getAttribute(name);
    if (text === null) return fallback;
    const value = text.trim().toLowerCase();
    if ((allowed as readonly string[]).includes(value)) return value as T;
    notices.push(message('elementAttributeInvalid', { name, text, allowed: allowed.join(', '), fallback }));
    return fallback;
  };
  // model-viewer's "auto" lets the browser decide; here that means lazy.
  const loading = choose('loading', LOADING, 'lazy') === 'eager' ? 'eager' : 'lazy';
  const reveal = choose('reveal', REVEAL, 'auto');
  const poster = element.getAttribute('poster')?.trim() || null;
  const alt = element.getAttribute('alt')?.trim() || null;
  return { options: { loading, reveal, poster, alt }, notices };
}
