import { overlaps, type Rect } from './rect';

/**
 * The largest rectangle of `view` that none of `obstacles` covers: the part of the canvas
 * that the control panel and the lessons drawer leave free, where the teaching views and
 * every overlay are laid out.
 *
 * The best rectangle's four edges each lie on the view's edge or on an obstacle's edge (else
 * it could grow), so trying every pair of such edges across and down finds it; a page has
 * two or three obstacles, a few hundred candidates. Ties go to the first found, which is
 * the leftmost, then the topmost.
 */
export function largestFreeRectangle(view: Rect, obstacles: readonly Rect[]): Rect {
  const inside = obstacles.filter((o) => o.width > 0 && o.height > 0 && overlaps(o, view));
  const clamp = (v: number, low: number, high: number) => Math.min(high, Math.max(low, v));
  const edges = (start: number, length: number, pick: (o: Rect) => [number, number]) =>
    [...new Set([start, start + length, ...inside.flatMap((o) => pick(o).map((v) => clamp(v, start, start + length)))])].sort(
      (a, b) => a - b,
    );
  const xs = edges(view.x, view.width, (o) => [o.x, o.x + o.width]);
  const ys = edges(view.y, view.height, (o) => [o.y, o.y + o.height]);
  let best: Rect = { x: view.x, y: view.y, width: 0, height: 0 };
  for (let a = 0; a < xs.length; a++) {
    for (let b = a + 1; b < xs.length; b++) {
      for (let c = 0; c < ys.length; c++) {
        for (let d = c + 1; d < ys.length; d++) {
          const candidate = { x: xs[a], y: ys[c], width: xs[b] - xs[a], height: ys[d] - ys[c] };
          if (candidate.width * candidate.height <= best.width * best.height) continue;
          if (!inside.some((o) => overlaps(o, candidate))) best = candidate;
        }
      }
    }
  }
  return best;
}
