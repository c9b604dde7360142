import type { Rect } from './rect';

/** Room kept around a figure inside its area, and under each picture for its caption (CSS px). */
export interface FigureSpacing {
  margin: number;
  gap: number;
  caption: number;
}

export const FIGURE_SPACING: FigureSpacing = { margin: 12, gap: 12, caption: 34 };

/**
 * `count` square pictures side by side, as large as fit in `area` with a margin round them,
 * a gap between them and a caption's height under each, the row centred in the area.
 * The teaching views (the Perlin stages, the heightmaps) draw into these squares and their
 * captions are placed under them, so picture and caption agree on the pixel.
 */
export function squaresInRow(count: number, area: Rect, spacing: FigureSpacing = FIGURE_SPACING): Rect[] {
  const across = (area.width - 2 * spacing.margin - (count - 1) * spacing.gap) / count;
  const down = area.height - 2 * spacing.margin - spacing.caption;
  const side = Math.max(0, Math.floor(Math.min(across, down)));
  const rowWidth = count * side + (count - 1) * spacing.gap;
  const left = area.x + (area.width - rowWidth) / 2;
  const top = area.y + (area.height - side - spacing.caption) / 2;
  return Array.from({ length: count }, (_, i) => ({
    x: Math.round(left + i * (side + spacing.gap)),
    y: Math.round(top),
    width: side,
    height: side,
  }));
}

/**
 * The largest box of `columns` × `rows` square cells that fits in `area` with the margin
 * round it and a caption's height under it, centred: the unfolded cube map's cross.
 */
export function cellGrid(columns: number, rows: number, area: Rect, spacing: FigureSpacing = FIGURE_SPACING): { box: Rect; cell: number } {
  const cell = Math.max(
    0,
    Math.floor(Math.min((area.width - 2 * spacing.margin) / columns, (area.height - 2 * spacing.margin - spacing.caption) / rows)),
  );
  const width = cell * columns;
  const height = cell * rows;
  return {
    box: {
      x: Math.round(area.x + (area.width - width) / 2),
      y: Math.round(area.y + (area.height - height - spacing.caption) / 2),
      width,
      height,
    },
    cell,
  };
}
