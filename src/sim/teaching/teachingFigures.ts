import { squaresInRow, cellGrid } from '../layout/figureLayout';
import type { Rect } from '../layout/rect';
import { CROSS_COLUMNS, CROSS_ROWS } from '../optics/cubeCross';

/**
 * The pictures a teaching view (the `view` parameter) draws instead of the sea, left to
 * right. `heightmap0/1`: the active model's two heightmaps as the vertex shader samples
 * them; the rest are the Perlin stages of src/sim/noise/noiseStages.ts, and `blend` the two
 * heightmaps mixed with the weight of the moment.
 */
export type PictureId = 'heightmap0' | 'heightmap1' | 'hash' | 'smoothed' | 'interpolated' | 'octaves' | 'first' | 'blend' | 'second';

export const FIGURE_PICTURES: Readonly<Record<string, readonly PictureId[]>> = {
  heightmap: ['heightmap0', 'heightmap1'],
  // One step per lesson, each beside the picture it starts from.
  'noise-hash': ['hash'],
  'noise-smoothing': ['hash', 'smoothed'],
  'noise-octaves': ['interpolated', 'octaves'],
  'noise-blend': ['first', 'blend', 'second'],
};

/** The view that shows the sky's cube map unfolded into a cross of its six faces. */
export const SKY_CUBE_VIEW = 'sky-cube';

/** Where each picture of `view` lies in `free` (the part of the canvas the panel and the drawer leave free), CSS px. */
export function figurePictures(view: string, free: Rect): { id: PictureId; rect: Rect }[] {
  const ids = FIGURE_PICTURES[view] ?? [];
  const rects = squaresInRow(ids.length, free);
  return ids.map((id, i) => ({ id, rect: rects[i] }));
}

/** Where the unfolded cube lies in `free`, and the side of one face, CSS px. */
export function crossPlacement(free: Rect): { box: Rect; cell: number } {
  return cellGrid(CROSS_COLUMNS, CROSS_ROWS, free);
}
