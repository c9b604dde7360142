import { largestFreeRectangle } from '../../sim/layout/freeRectangle';
import type { Rect } from '../../sim/layout/rect';
import { FREE_AREA_EVENT } from './freeAreaEvent';

const areas = new WeakMap<HTMLElement, FreeArea>();

/**
 * The part of a view's canvas that its own panels (the control panel, the lessons drawer)
 * leave free: the largest rectangle none of them covers, measured whenever one of them or
 * the canvas changes size. The compare strips and the teaching views are laid out in it
 * (the renderer hears of it through FREE_AREA_EVENT), and so is every overlay: the
 * stylesheets read it as --oceano-free-left, -top, -right, -bottom, -width and -height.
 * A view without panels (a figure in a course page) never loads this: all of it is free.
 */
export class FreeArea {
  private readonly obstacles = new Set<HTMLElement>();
  private readonly observer = new ResizeObserver(() => this.measure());
  private canvas: HTMLCanvasElement | null = null;
  rect: Rect | null = null;

  /** The one free area of a view's container, made the first time a panel asks for it. */
  static of(container: HTMLElement): FreeArea {
    let area = areas.get(container);
    if (!area) areas.set(container, (area = new FreeArea(container)));
    return area;
  }

  private constructor(private readonly container: HTMLElement) {}

  /** Keeps the free area clear of `element` while it is shown. */
  avoid(element: HTMLElement): void {
    this.obstacles.add(element);
    this.observer.observe(element);
    this.measure();
  }

  release(element: HTMLElement): void {
    this.obstacles.delete(element);
    this.observer.unobserve(element);
    this.measure();
  }

  measure(): void {
    const canvas = this.container.querySelector<HTMLCanvasElement>(':scope > canvas');
    if (!canvas) return;
    if (canvas !== this.canvas) {
      this.canvas = canvas;
      this.observer.observe(canvas);
    }
    const box = canvas.getBoundingClientRect();
    const obstacles = [...this.obstacles]
      .filter((element) => element.isConnected && element.getClientRects().length > 0)
      .map((element) => {
        const r = element.getBoundingClientRect();
        return { x: r.left - box.left, y: r.top - box.top, width: r.width, height: r.height };
      });
    const found = largestFreeRectangle({ x: 0, y: 0, width: box.width, height: box.height }, obstacles);
    // Whole pixels, rounded inwards: an overlay placed at the edge never touches a panel.
    const x = Math.ceil(found.x);
    const y = Math.ceil(found.y);
    const rect = { x, y, width: Math.floor(found.x + found.width) - x, height: Math.floor(found.y + found.height) - y };
    const last = this.rect;
    if (last && last.x === rect.x && last.y === rect.y && last.width === rect.width && last.height === rect.height) return;
    this.rect = rect;
    const style = this.container.style;
    const px = (name: string, value: number) => style.setProperty(`--oceano-free-${name}`, `${value}px`);
    px('left', rect.x);
    px('top', rect.y);
    px('width', rect.width);
    px('height', rect.height);
    px('right', Math.round(box.width) - rect.x - rect.width);
    px('bottom', Math.round(box.height) - rect.y - rect.height);
    this.container.dispatchEvent(new CustomEvent(FREE_AREA_EVENT, { detail: rect }));
  }
}
