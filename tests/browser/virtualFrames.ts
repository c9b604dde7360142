/**
 * requestAnimationFrame driven by the test: frames come every 1000/60 ms of a virtual clock,
 * by themselves until `manualFrames()` is called, then only when `pumpFrames(n)` runs them
 * (until `autoFrames()`: the screenshot waits for frames of its own). Text, not a function:
 * the test runner's transform would give its inner functions helpers the page lacks.
 */
export const VIRTUAL_FRAMES = `(() => {
  let queue = new Map();
  let next = 1;
  let now = 0;
  let manual = false;
  function pump() {
    const due = queue;
    queue = new Map();
    now += 1000 / 60;
    for (const callback of due.values()) callback(now);
  }
  setInterval(() => { if (!manual) pump(); }, 16);
  window.requestAnimationFrame = (callback) => { queue.set(next, callback); return next++; };
  window.cancelAnimationFrame = (id) => { queue.delete(id); };
  window.manualFrames = () => { manual = true; };
  window.autoFrames = () => { manual = false; };
  window.pumpFrames = (n) => { for (let i = 0; i < n; i++) pump(); };
})();`;

export type Pumped = Window & { manualFrames(): void; autoFrames(): void; pumpFrames(n: number): void };
