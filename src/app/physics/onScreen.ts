/**
 * Waits until some part of `element` is on screen. A measurement of the sea holds the page's
 * one thread for seconds: a figure that starts half a screen before it is seen, or is released
 * before it is, must not spend them while the figures the reader is looking at wait.
 */
export function onScreen(element: Element): { shown: Promise<void>; cancel(): void } {
  if (typeof IntersectionObserver !== 'function') return { shown: Promise.resolve(), cancel: () => {} };
  let watch: IntersectionObserver | null = null;
  const shown = new Promise<void>((resolve) => {
    watch = new IntersectionObserver((entries) => {
      if (!entries.some((entry) => entry.isIntersecting)) return;
      watch?.disconnect();
      resolve();
    });
    watch.observe(element);
  });
  return { shown, cancel: () => (watch as IntersectionObserver | null)?.disconnect() };
}
