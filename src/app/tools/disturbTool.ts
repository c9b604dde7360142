import { horizontalDistance } from '../../sim/tools/rulerDistance';
import { toolWord } from '../language/toolWords';
import type { SeaTool, SeaToolContext, SeaXZ } from './seaTool';

/** While dragging, a new stone is dropped each time the pointer has moved this far over the sea, m: a trail of rings, not a smear. */
const DRAG_SPACING = 1.5;

/**
 * Stones: a click on the sea drops one into the interactive waves (iWave, src/sim/iwave/)
 * where it lands, a drag drops a trail of them, and a button drops one at the centre of the
 * view (the point the camera orbits) for those without a pointer.
 */
export class DisturbTool implements SeaTool {
  readonly body = document.createElement('section');
  private last: SeaXZ | null = null;
  private dropped = 0;
  private readonly count = document.createElement('p');

  constructor(private readonly context: SeaToolContext) {
    this.body.className = 'oceano-tool-disturb';
    const centre = document.createElement('button');
    centre.type = 'button';
    centre.className = 'oceano-tool-button';
    centre.textContent = toolWord(context.tr, 'dropCentre');
    centre.addEventListener('click', () => {
      const [x, , z] = context.pose().target;
      void this.drop({ x, z });
    });
    this.count.className = 'oceano-tool-note';
    this.body.append(centre, this.count);
  }

  holdsMeasurement(): boolean {
    return false;
  }

  /** Drops a stone at `point`; settles once it is in the water. */
  drop(point: SeaXZ): Promise<void> {
    this.last = point;
    return this.context.dropStone(point).then(() => {
      this.dropped++;
      this.count.textContent = toolWord(this.context.tr, 'stoneDropped', { n: this.dropped });
    });
  }

  down(point: SeaXZ): void {
    void this.drop(point);
  }

  drag(point: SeaXZ): void {
    if (!this.last || horizontalDistance(this.last, point) >= DRAG_SPACING) void this.drop(point);
  }

  enter(point: SeaXZ): void {
    void this.drop(point);
  }

  /** A line under the button: what the tool did besides dropping stones (it turned the interactive waves on). */
  say(text: string): void {
    this.count.textContent = text;
  }

  cursorMoved(): void {}
  frame(): void {}
  placeLabels(): void {}
  clear(): void {}
  dispose(): void {}
}
