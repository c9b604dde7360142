import { message } from '../../sim/params/message';
import type { OceanApp } from '../oceanApp';
import type { Translator } from '../language/i18n';

/**
 * Asks for a throwaway WebGL2 context and gives it straight back: browsers keep only about
 * sixteen alive, and a page of figures must not spend them on probes.
 */
export function hasWebGL2(): boolean {
  try {
    const gl = document.createElement('canvas').getContext('webgl2');
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
    return gl !== null;
  } catch {
    return false;
  }
}

/** Words in place of the canvas, and of the loading steps, when the ocean cannot run at all. */
export function showFatal(container: HTMLElement, text: string): void {
  container.querySelector(':scope > .oceano-loading')?.remove();
  const box = document.createElement('div');
  box.className = 'oceano-fatal';
  box.setAttribute('role', 'alert');
  box.textContent = text;
  container.appendChild(box);
}

/** Starts the app; a failure replaces the view with a readable message and rejects `ready`. */
export function startApp(app: OceanApp, container: HTMLElement, tr: Translator): Promise<void> {
  return app.start().catch((error: unknown) => {
    console.error('Oceano could not start:', error);
    showFatal(container, tr.message(message('startFailed', { error: error instanceof Error ? error.message : String(error) })));
    throw error;
  });
}

export function prefersReducedMotion(): boolean {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}

/**
 * Stops an app's frame loop while the tab is hidden and, given an element, while that
 * element is scrolled out of view. Returns the function that stops watching.
 */
export function watchActivity(app: OceanApp, element?: HTMLElement): () => void {
  const onVisibility = () => app.setSuspended('hidden', document.visibilityState === 'hidden');
  document.addEventListener('visibilitychange', onVisibility);
  onVisibility();
  let observer: IntersectionObserver | undefined;
  if (element && typeof IntersectionObserver === 'function') {
    observer = new IntersectionObserver((entries) => {
      const last = entries[entries.length - 1];
      app.setSuspended('offscreen', !last.isIntersecting);
    });
    observer.observe(element);
  }
  return () => {
    document.removeEventListener('visibilitychange', onVisibility);
    observer?.disconnect();
  };
}
