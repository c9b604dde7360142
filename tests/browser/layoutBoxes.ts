import type { Page } from 'puppeteer';
import { largestFreeRectangle } from '../../src/sim/layout/freeRectangle';
import type { Rect } from '../../src/sim/layout/rect';

/** The overlays laid out in the free part of a view (the part no panel covers), by the class each carries. */
export const OVERLAYS = {
  fresnelPlot: '.oceano-fresnel-plot',
  physicsPanel: '.oceano-physics',
  compareLabel: '.oceano-compare-label',
  compareDivider: '.oceano-compare-divider',
  figureCaption: '.oceano-figure-caption',
  lessonLabel: '.oceano-lesson-label',
  playButton: '.oceano-play',
  seaTools: '.oceano-sea-tools',
} as const;

/** What takes room from the canvas: the lessons drawer and the control panel. */
const PANELS = '.oceano-lessons, .lil-gui.lil-root';

export interface ViewBoxes {
  canvas: Rect;
  /** The drawer's and the panel's boxes, as shown. */
  panels: Rect[];
  /** The free part the page published (--oceano-free-*), or the whole canvas where it published none. */
  published: Rect;
  /** Every shown overlay's box, with its kind and its text. */
  overlays: { kind: keyof typeof OVERLAYS; text: string; box: Rect }[];
}

/**
 * The boxes of one view (the page's #oceano-page, or an <oceano-view>), in CSS px from the
 * canvas's top left. A divider's box is its 2-px line (its 16-px grab area may reach past it).
 */
export async function viewBoxes(page: Page, container = '#oceano-page'): Promise<ViewBoxes> {
  return page.evaluate(
    (containerSelector, panelSelector, overlays) => {
      const root = document.querySelector<HTMLElement>(containerSelector)!;
      const canvasBox = root.querySelector(':scope > canvas')!.getBoundingClientRect();
      const relative = (r: DOMRect) => ({ x: r.left - canvasBox.left, y: r.top - canvasBox.top, width: r.width, height: r.height });
      const shown = (el: Element) => (el as HTMLElement).getClientRects().length > 0 && getComputedStyle(el).visibility !== 'hidden';
      const style = getComputedStyle(root);
      const variable = (name: string) => style.getPropertyValue(`--oceano-free-${name}`).trim();
      const published = variable('left')
        ? {
            x: parseFloat(variable('left')),
            y: parseFloat(variable('top')),
            width: parseFloat(variable('width')),
            height: parseFloat(variable('height')),
          }
        : { x: 0, y: 0, width: canvasBox.width, height: canvasBox.height };
      const boxes: { kind: string; text: string; box: { x: number; y: number; width: number; height: number } }[] = [];
      for (const [kind, selector] of Object.entries(overlays)) {
        for (const el of root.querySelectorAll(selector)) {
          if (!shown(el)) continue;
          const r = el.getBoundingClientRect();
          const line = kind === 'compareDivider' ? new DOMRect(r.left + r.width / 2 - 1, r.top, 2, r.height) : r;
          boxes.push({ kind, text: (el.textContent ?? '').trim(), box: relative(line) });
        }
      }
      return {
        canvas: { x: 0, y: 0, width: canvasBox.width, height: canvasBox.height },
        panels: Array.from(root.querySelectorAll(panelSelector))
          .filter(shown)
          .map((el) => relative(el.getBoundingClientRect())),
        published,
        overlays: boxes,
      };
    },
    container,
    PANELS,
    OVERLAYS,
  ) as Promise<ViewBoxes>;
}

/** The free part as the test measures it, independently of the page: the largest rectangle the panels leave. */
export function measuredFreeArea(boxes: ViewBoxes): Rect {
  return largestFreeRectangle(boxes.canvas, boxes.panels);
}

/** The overlays that stick out of `free` by more than half a pixel. */
export function outside(boxes: ViewBoxes, free: Rect): string[] {
  const inside = (b: Rect) =>
    b.x >= free.x - 0.5 &&
    b.y >= free.y - 0.5 &&
    b.x + b.width <= free.x + free.width + 0.5 &&
    b.y + b.height <= free.y + free.height + 0.5;
  return boxes.overlays
    .filter((o) => !inside(o.box))
    .map((o) => `${o.kind} "${o.text.slice(0, 30)}" at ${[o.box.x, o.box.y, o.box.width, o.box.height].map(Math.round).join(',')}`);
}

/** Adds CSS rules to a page, a strict Content-Security-Policy's included (a constructed sheet is no inline style). */
export async function addRules(page: Page, css: string): Promise<void> {
  await page.evaluate((text) => {
    const sheet = new CSSStyleSheet();
    sheet.replaceSync(text);
    document.adoptedStyleSheets = [...document.adoptedStyleSheets, sheet];
  }, css);
}
