import type { Diagram, DiagramLine, LineRole, Point } from '../../../sim/teaching/diagrams/diagram';
import type { Language } from '../../language/i18n';
import { diagramDescription, diagramName, markLabel } from './diagramLabels';
import { DIAGRAM_WORDS } from './diagramWords';

const SVG = 'http://www.w3.org/2000/svg';
/**
 * The drawing's width in its own units. It scales to the card: about 1:1 in a laptop's
 * 250 px card, larger on a phone, where the card is the screen's width.
 */
const WIDTH = 250;
const GRAPH_HEIGHT = 160;
const GRAPH_PAD = { left: 24, right: 6, top: 10, bottom: 20 };
const PICTURE_PAD = 8;
const PICTURE_HEIGHT: readonly [number, number] = [90, 190];

const STROKES: Readonly<Record<LineRole, { color: string; width: number; dash?: string }>> = {
  main: { color: '#7fd4ff', width: 2 },
  second: { color: '#ffd75e', width: 1.6 },
  guide: { color: '#b7e59a', width: 1.3, dash: '4 3' },
  faint: { color: 'rgba(232, 242, 247, 0.4)', width: 1 },
};

let clipCount = 0;

function svg<K extends keyof SVGElementTagNameMap>(tag: K, attributes: Record<string, string | number>): SVGElementTagNameMap[K] {
  const el = document.createElementNS(SVG, tag);
  for (const [name, value] of Object.entries(attributes)) el.setAttribute(name, String(value));
  return el;
}

/** Linear RGB (0..1) as the sRGB hex the LOD view's tint shows on screen. */
function srgbHex(color: readonly [number, number, number]): string {
  const encode = (c: number) => (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055);
  return `#${color
    .map((c) =>
      Math.round(255 * Math.min(1, Math.max(0, encode(c))))
        .toString(16)
        .padStart(2, '0'),
    )
    .join('')}`;
}

/** The drawing box and the map from diagram units into it. */
function frame(diagram: Diagram): {
  height: number;
  map: (p: Point) => [number, number];
  plot: { x: number; y: number; width: number; height: number };
} {
  const [x0, x1] = diagram.x;
  const [y0, y1] = diagram.y;
  if (!diagram.equalScale) {
    const graphHeight = diagram.graphHeight ?? GRAPH_HEIGHT;
    const plot = {
      x: GRAPH_PAD.left,
      y: GRAPH_PAD.top,
      width: WIDTH - GRAPH_PAD.left - GRAPH_PAD.right,
      height: graphHeight - GRAPH_PAD.top - GRAPH_PAD.bottom,
    };
    return {
      height: graphHeight,
      plot,
      map: ([x, y]) => [plot.x + ((x - x0) / (x1 - x0)) * plot.width, plot.y + (1 - (y - y0) / (y1 - y0)) * plot.height],
    };
  }
  const inner = WIDTH - 2 * PICTURE_PAD;
  const scale = Math.min(inner / (x1 - x0), PICTURE_HEIGHT[1] / (y1 - y0));
  const plotHeight = Math.max(PICTURE_HEIGHT[0], (y1 - y0) * scale);
  const height = plotHeight + 2 * PICTURE_PAD;
  const left = PICTURE_PAD + (inner - (x1 - x0) * scale) / 2;
  const top = PICTURE_PAD + (plotHeight - (y1 - y0) * scale) / 2;
  return {
    height,
    plot: { x: PICTURE_PAD, y: PICTURE_PAD, width: inner, height: plotHeight },
    map: ([x, y]) => [left + (x - x0) * scale, top + (y1 - y) * scale],
  };
}

/**
 * Draws a lesson's Diagram as SVG in a figure, its caption saying which line is which. The
 * figure is an image to assistive technology (role="img"), named by the key value it shows.
 */
export class DiagramSvg {
  readonly element: HTMLElement;
  private readonly svg: SVGSVGElement;
  private readonly caption: HTMLElement;

  constructor(private readonly language: Language) {
    this.element = document.createElement('figure');
    this.element.className = 'oceano-lesson-diagram';
    this.element.style.margin = '0 0 8px';
    this.svg = svg('svg', { role: 'img', width: '100%' });
    this.svg.style.display = 'block';
    this.svg.style.maxWidth = '420px';
    this.caption = document.createElement('figcaption');
    this.caption.style.fontSize = '11px';
    this.caption.style.opacity = '0.85';
    this.element.append(this.svg, this.caption);
  }

  render(diagram: Diagram): void {
    const language = this.language;
    const words = DIAGRAM_WORDS[diagram.kind];
    const { height, map, plot } = frame(diagram);
    const name = diagramName(diagram, language);
    this.svg.setAttribute('viewBox', `0 0 ${WIDTH} ${height.toFixed(1)}`);
    this.svg.setAttribute('aria-label', name);
    this.svg.dataset.kind = diagram.kind;
    this.svg.dataset.headline = String(diagram.marks.find((m) => m.id === diagram.headline)?.value ?? '');
    const title = svg('title', {});
    title.textContent = `${name}. ${diagramDescription(diagram, language)}`;
    const clipId = `oceano-diagram-clip-${++clipCount}`;
    const clip = svg('clipPath', { id: clipId });
    clip.append(svg('rect', { x: plot.x, y: plot.y, width: plot.width, height: plot.height }));
    const defs = svg('defs', {});
    defs.append(clip);
    const drawing = svg('g', { 'clip-path': `url(#${clipId})`, fill: 'none', 'stroke-linejoin': 'round', 'stroke-linecap': 'round' });
    for (const line of diagram.lines) drawing.append(this.polyline(line, map));
    const parts: SVGElement[] = [title, defs];
    if (!diagram.equalScale) parts.push(...this.axes(plot, words.xAxis?.[language], words.yAxis?.[language]));
    parts.push(drawing);
    for (const mark of diagram.marks) {
      const [x, y] = map([mark.x, mark.y]);
      if (!mark.bare)
        parts.push(svg('circle', { cx: x.toFixed(1), cy: y.toFixed(1), r: 3, fill: '#ffffff', stroke: '#082d3f', 'stroke-width': 1 }));
      if (mark.quiet) continue;
      // A note reads from where it stands unless that is near the right edge; a dot's label leans away from the edge.
      const right = x > WIDTH * (mark.bare ? 0.8 : 0.62);
      const text = svg('text', {
        x: (x + (mark.bare || mark.centred ? 0 : right ? -5 : 5)).toFixed(1),
        y: Math.min(height - 3, Math.max(10, y + (mark.below ? 13 : -5))).toFixed(1),
        'text-anchor': mark.centred ? 'middle' : right ? 'end' : 'start',
        ...TEXT,
      });
      text.textContent = markLabel(diagram, mark, language);
      parts.push(text);
    }
    this.svg.replaceChildren(...parts);
    this.caption.textContent = words.key[language];
  }

  private polyline(line: DiagramLine, map: (p: Point) => [number, number]): SVGPolylineElement {
    const stroke = STROKES[line.role];
    const attributes: Record<string, string | number> = {
      points: line.points
        .map((p) =>
          map(p)
            .map((v) => v.toFixed(1))
            .join(','),
        )
        .join(' '),
      stroke: line.color ? srgbHex(line.color) : stroke.color,
      'stroke-width': line.color ? 6 : stroke.width,
    };
    if (stroke.dash) attributes['stroke-dasharray'] = stroke.dash;
    return svg('polyline', attributes);
  }

  private axes(plot: { x: number; y: number; width: number; height: number }, xTitle?: string, yTitle?: string): SVGElement[] {
    const bottom = plot.y + plot.height;
    const axis = { fill: 'none', stroke: 'rgba(232, 242, 247, 0.6)', 'stroke-width': 1 };
    // Only a quantity has an axis: the butterflies' rows are no scale.
    const parts: SVGElement[] = [];
    if (xTitle) parts.push(svg('polyline', { points: `${plot.x},${bottom} ${plot.x + plot.width},${bottom}`, ...axis }));
    if (yTitle) parts.push(svg('polyline', { points: `${plot.x},${plot.y} ${plot.x},${bottom}`, ...axis }));
    if (xTitle) {
      const t = svg('text', { x: plot.x + plot.width, y: bottom + 15, 'text-anchor': 'end', ...TEXT });
      t.textContent = xTitle;
      parts.push(t);
    }
    if (yTitle) {
      const t = svg('text', {
        x: 10,
        y: plot.y + plot.height / 2,
        'text-anchor': 'middle',
        transform: `rotate(-90 10 ${plot.y + plot.height / 2})`,
        ...TEXT,
      });
      t.textContent = yTitle;
      parts.push(t);
    }
    return parts;
  }
}

/** Text light on the card, ringed in its dark blue so it reads over a line. */
const TEXT = {
  'font-size': 10,
  fill: '#e8f2f7',
  stroke: 'rgba(8, 30, 45, 0.9)',
  'stroke-width': 2.5,
  'paint-order': 'stroke',
  'font-family': 'system-ui, sans-serif',
} as const;
