import { Vector3 } from 'three';
import { along, horizontalDistance } from '../../sim/tools/rulerDistance';
import { SeaLine, SeaPin } from '../../render/teaching/seaMarkers';
import { toolNumber, toolWord } from '../language/toolWords';
import { FreeArea } from '../layout/freeArea';
import type { SeaTool, SeaToolContext, SeaXZ } from './seaTool';

const RULER_COLOUR = 0xffe066;
/** Points of the line laid on the sea between the two ends: enough to follow a 10 m wave across 100 m. */
const LINE_POINTS = 129;
/** The line floats this far above the surface, m, so it reads as lying on the water rather than cutting it. */
const LIFT = 0.05;

/**
 * The ruler: two ends on the sea and the horizontal distance between them, drawn as a line
 * that follows the waves with its length written at its middle. Set by dragging (from where
 * the pointer goes down to where it is let go) or from the keyboard (Enter fixes the first
 * end, then the second follows the keyboard's point until Enter fixes it).
 */
export class RulerTool implements SeaTool {
  readonly body = document.createElement('section');
  private a: SeaXZ | null = null;
  private b: SeaXZ | null = null;
  /** True between the keyboard's first Enter and its second: the second end follows the keyboard's point. */
  private placing = false;
  private readonly line = new SeaLine(LINE_POINTS, RULER_COLOUR);
  private readonly ends = [new SeaPin(RULER_COLOUR), new SeaPin(RULER_COLOUR)];
  private readonly distance = document.createElement('p');
  private readonly detail = document.createElement('p');
  readonly label = document.createElement('div');

  constructor(
    private readonly context: SeaToolContext,
    overlay: HTMLElement,
  ) {
    this.body.className = 'oceano-tool-ruler';
    this.distance.className = 'oceano-ruler-distance';
    this.detail.className = 'oceano-tool-note';
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.className = 'oceano-tool-button';
    remove.textContent = toolWord(context.tr, 'remove');
    remove.setAttribute('aria-label', toolWord(context.tr, 'rulerRemove'));
    remove.addEventListener('click', () => this.clear());
    const head = document.createElement('div');
    head.className = 'oceano-tool-row';
    head.append(this.distance, remove);
    this.body.append(head, this.detail);
    this.label.className = 'oceano-ruler-label';
    this.label.hidden = true;
    overlay.append(this.label);
    context.scene.add(this.line.object, ...this.ends.map((end) => end.object));
    this.show();
  }

  holdsMeasurement(): boolean {
    return this.a !== null;
  }

  /** The ends and the distance between them, metres (null without a ruler). */
  reading(): { a: SeaXZ; b: SeaXZ; distance: number } | null {
    return this.a && this.b ? { a: { ...this.a }, b: { ...this.b }, distance: horizontalDistance(this.a, this.b) } : null;
  }

  down(point: SeaXZ): void {
    this.placing = false;
    this.set(point, point);
  }

  drag(point: SeaXZ): void {
    if (this.a) this.set(this.a, point);
  }

  enter(point: SeaXZ): void {
    if (this.placing && this.a) {
      this.placing = false;
      this.set(this.a, point);
    } else {
      this.placing = true;
      this.set(point, point);
    }
  }

  cursorMoved(point: SeaXZ): void {
    if (this.placing && this.a) this.set(this.a, point);
  }

  private set(a: SeaXZ, b: SeaXZ): void {
    this.a = { x: a.x, z: a.z };
    this.b = { x: b.x, z: b.z };
    this.show();
    this.context.redraw();
  }

  frame(): void {
    if (!this.a || !this.b) return;
    const camera = this.context.camera;
    for (let i = 0; i < LINE_POINTS; i++) {
      const p = along(this.a, this.b, i / (LINE_POINTS - 1));
      this.line.set(i, p.x, this.context.height(p.x, p.z) + LIFT, p.z);
    }
    this.line.show();
    [this.a, this.b].forEach((end, i) => this.ends[i].place(end.x, this.context.height(end.x, end.z), end.z, camera));
  }

  /** The length written at the line's middle, where that is on the canvas. */
  placeLabels(): void {
    if (!this.a || !this.b) {
      this.label.hidden = true;
      return;
    }
    const middle = along(this.a, this.b, 0.5);
    const canvas = this.context.canvas;
    const p = new Vector3(middle.x, this.context.height(middle.x, middle.z), middle.z).project(this.context.camera);
    let x = ((p.x + 1) / 2) * canvas.clientWidth;
    let y = ((1 - p.y) / 2) * canvas.clientHeight;
    // Only in the part of the canvas the panels leave free, as the lessons' labels (the whole canvas in a figure without panels).
    const free = (canvas.parentElement && FreeArea.of(canvas.parentElement).rect) || {
      x: 0,
      y: 0,
      width: canvas.clientWidth,
      height: canvas.clientHeight,
    };
    const visible = Math.abs(p.z) <= 1 && x >= free.x && x <= free.x + free.width && y >= free.y && y <= free.y + free.height;
    this.label.hidden = !visible;
    if (!visible) return;
    // The label's box starts 20 px left of and 24 px above the point (seaTools.css): slid back in where it would cross the edge.
    x = Math.max(free.x + 20, Math.min(x, free.x + free.width + 20 - this.label.offsetWidth));
    y = Math.max(free.y + 24, y);
    this.label.style.transform = `translate(${x.toFixed(1)}px, ${y.toFixed(1)}px)`;
  }

  private show(): void {
    const tr = this.context.tr;
    const reading = this.reading();
    this.body.classList.toggle('oceano-tool-empty', !reading);
    if (!reading) {
      this.distance.textContent = toolWord(tr, 'rulerNone');
      this.detail.textContent = '';
      this.label.hidden = true;
      return;
    }
    const d = toolNumber(tr, reading.distance, 2);
    this.distance.textContent = toolWord(tr, 'rulerDistance', { d });
    this.label.textContent = `${d} m`;
    const c = (v: number) => toolNumber(tr, v, 1);
    this.detail.textContent = this.placing
      ? toolWord(tr, 'rulerFirst')
      : toolWord(tr, 'rulerEnds', { ax: c(reading.a.x), az: c(reading.a.z), bx: c(reading.b.x), bz: c(reading.b.z) });
  }

  clear(): void {
    this.a = null;
    this.b = null;
    this.placing = false;
    this.line.hide();
    for (const end of this.ends) end.hide();
    this.show();
    this.context.redraw();
  }

  dispose(): void {
    this.line.dispose();
    for (const end of this.ends) end.dispose();
    this.label.remove();
  }
}
