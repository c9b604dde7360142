/**
 * What a lesson's flat diagram draws, in its own units (wavenumber and frequency, metres,
 * degrees): polylines, and marked points that carry the value they stand for. The app turns
 * it into SVG and words (src/app/lessons/diagrams/); nothing here knows about pixels.
 */
export type Point = readonly [number, number];

/** main: the curve the lesson is about; second: the one it is compared with; guide: a construction line; faint: context. */
export type LineRole = 'main' | 'second' | 'guide' | 'faint';

export interface DiagramLine {
  points: readonly Point[];
  role: LineRole;
  /** Linear RGB, 0..1, where the sea shows the same thing in a colour of its own (the LOD bands). */
  color?: readonly [number, number, number];
}

export interface DiagramMark {
  /** Which label it takes (the app's words for `${kind}.${id}`). */
  id: string;
  x: number;
  y: number;
  /** The value the label states, in `unit`. */
  value: number;
  unit: string;
  /** Where a mark is one of a series (crest n, band b), its index. */
  index?: number;
  /** A label without a dot: a note placed in the picture rather than a point on a curve. */
  bare?: boolean;
  /** A dot without a label, where labels would crowd (the innermost crests). */
  quiet?: boolean;
  /** Its label below the point rather than above. */
  below?: boolean;
  /** Its label centred on the point (marks in a row whose labels would otherwise run into each other). */
  centred?: boolean;
}

export interface Diagram {
  kind: DiagramKind;
  /** The drawn window, [min, max] on each axis. */
  x: Point;
  y: Point;
  /** One metre (or unit) the same length across and up: a picture of space rather than a graph. */
  equalScale: boolean;
  lines: DiagramLine[];
  marks: DiagramMark[];
  /** A graph's height in the drawing's units where the default would crowd it (the app's own default otherwise). */
  graphHeight?: number;
  /** The mark whose value the diagram's accessible name states. */
  headline: string;
}

export type DiagramKind =
  | 'seedDispersion'
  | 'depthDispersion'
  | 'orbit'
  | 'snell'
  | 'spectrum'
  | 'butterflies'
  | 'lodBands'
  | 'kelvin'
  | 'cauchyPoisson'
  | 'fresnel';

/** Samples f on [a, b] at n + 1 evenly spaced points. */
export function sampled(a: number, b: number, n: number, f: (t: number) => Point): Point[] {
  return Array.from({ length: n + 1 }, (_, i) => f(a + ((b - a) * i) / n));
}

export const DEGREE = Math.PI / 180;

export function headlineMark(diagram: Diagram): DiagramMark {
  const mark = diagram.marks.find((m) => m.id === diagram.headline);
  if (!mark) throw new Error(`Diagram ${diagram.kind} has no mark ${diagram.headline}.`);
  return mark;
}
