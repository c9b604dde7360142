/**
 * Waits until some part of `element` is on screen. A measurement of the sea costs seconds of
 * the page's one thread: a figure that starts half a screen before it is seen, or is given back
 * before it is, must not spend them. `settled` also settles on `cancel()` (the caller then checks
 * whether it still wants the measurement), so nothing waits on it for ever.
 */
export function onScreen(element: Element): { settled: Promise<void>; cancel(): void } {
  if (typeof IntersectionObserver !== 'function') return { settled: Promise.resolve(), cancel: () => {} };
  let stop = () => {};
  const settled = new Promise<void>((resolve) => {
    const watch = new IntersectionObserver((entries) => {
      if (entries.some((entry) => entry.isIntersecting)) stop();
    });
    stop = () => {
      watch.disconnect();
      resolve();
    };
    watch.observe(element);
  });
  return { settled, cancel: () => stop() };
}
