/**
 * The side-by-side view (`compare=seed,gerstner,fft`): which models, in which order, and
 * which columns of the drawing buffer each one draws. Pure arithmetic, so the page's
 * dividers, the renderer's scissor rectangles and the tests agree on the same pixels.
 */

/** The `compare` value that turns the split off. */
export const COMPARE_OFF = 'off';

/**
 * Every ordered choice of two or three distinct models, written `a,b` or `a,b,c`: the
 * options of the `compare` parameter. Order matters (the first model is drawn on the left
 * and carries the boat), so `seed,gerstner` and `gerstner,seed` are both listed.
 */
export function compareOrderings(models: readonly string[]): string[] {
  const pairs: string[] = [];
  const triples: string[] = [];
  for (const a of models) {
    for (const b of models) {
      if (b === a) continue;
      pairs.push(`${a},${b}`);
      for (const c of models) if (c !== a && c !== b) triples.push(`${a},${b},${c}`);
    }
  }
  return [...pairs, ...triples];
}

/** The models named by a valid `compare` value, left to right; none when it is off. */
export function compareModelNames<M extends string>(compare: string): M[] {
  return compare === COMPARE_OFF ? [] : (compare.split(',') as M[]);
}

/**
 * Where the dividers stand, as fractions of the width, for `count` strips: the first at
 * `split`, the second (three models) at `split2` but never left of the first.
 */
export function dividerPositions(count: number, split: number, split2: number): number[] {
  const first = Math.min(1, Math.max(0, split));
  if (count <= 1) return [];
  if (count === 2) return [first];
  return [first, Math.min(1, Math.max(first, split2))];
}

/** One model's columns of the drawing buffer, [x0, x1) in pixels from the left. */
export interface Strip {
  x0: number;
  x1: number;
}

/**
 * The columns each of `count` models draws in a buffer `width` pixels wide. The dividers
 * stand in the columns [from, to) (the part of the view that the page's panels leave
 * free): one at fraction f falls on pixel column round(from + f · (to − from)), and the
 * page puts its divider element at the same place, so the boundary seen and the boundary
 * drawn agree to one pixel. The outer strips reach the buffer's edges, under the panels.
 * Strips tile the width exactly, without gap or overlap; a strip may be empty.
 */
export function compareStrips(count: number, split: number, split2: number, width: number, from = 0, to = width): Strip[] {
  const edges = [0, ...dividerPositions(count, split, split2).map((f) => Math.round(from + f * (to - from))), width];
  const strips: Strip[] = [];
  for (let i = 0; i + 1 < edges.length; i++) strips.push({ x0: edges[i], x1: edges[i + 1] });
  return strips;
}
