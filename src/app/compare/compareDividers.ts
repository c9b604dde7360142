import { COMPARE_OFF, compareModelNames, dividerPositions } from '../../sim/compare/compareLayout';
import type { OceanParams } from '../../sim/params/params';
import type { Translator } from '../language/i18n';
import { FREE_AREA_EVENT } from '../layout/freeAreaEvent';

export type SplitKey = 'compareSplit' | 'compareSplit2';
const SPLIT_KEYS: readonly SplitKey[] = ['compareSplit', 'compareSplit2'];
/** One arrow key press moves a divider by 1 % of the width; Page Up/Down by 10 %. */
const KEY_STEP = 0.01;
const PAGE_STEP = 0.1;

/** Fractions kept to the parameter's step (0.001), so a dragged split reads back cleanly in a share link. */
const onStep = (f: number) => Math.round(f * 1000) / 1000;

/**
 * compare=a,b[,c]: the dividers between the models, as HTML over the canvas (never drawn
 * into it, so every canvas pixel stays the models' own). Each is a focusable ARIA separator
 * whose value is its position in percent; dragging it or pressing the arrow keys sets
 * compareSplit / compareSplit2 through the app, as the GUI and the API do. The overlay
 * covers the part of the canvas the panels leave free (widgets.css), so the dividers and
 * the models' names stay in sight; a name that would cross the overlay's edge slides back in.
 */
export class CompareDividers {
  private readonly overlay: HTMLElement;
  private dividers: HTMLElement[] = [];
  private compare = COMPARE_OFF;
  /** Where the dividers are drawn now (fractions of the width), for clamping a drag between them. */
  private shown: number[] = [];

  constructor(
    private readonly container: HTMLElement,
    private readonly tr: Translator,
    private readonly setSplit: (key: SplitKey, value: number) => void,
  ) {
    this.overlay = document.createElement('div');
    this.overlay.className = 'oceano-compare';
    this.overlay.hidden = true;
    container.appendChild(this.overlay);
    container.addEventListener(FREE_AREA_EVENT, this.keepLabelsInside);
  }

  sync(params: OceanParams): void {
    if (params.compare !== this.compare) this.build(params.compare);
    this.shown = dividerPositions(this.dividers.length + 1, params.compareSplit, params.compareSplit2);
    const names = compareModelNames<string>(this.compare);
    this.dividers.forEach((divider, i) => {
      const f = this.shown[i];
      divider.style.left = `${f * 100}%`;
      const percent = Math.round(f * 1000) / 10;
      divider.setAttribute('aria-valuenow', String(percent));
      divider.setAttribute('aria-valuetext', `${names[i]} | ${names[i + 1]}: ${percent} %`);
    });
    this.keepLabelsInside();
  }

  /** Slides each model's name back inside the overlay where its divider stands near an edge. */
  private readonly keepLabelsInside = (): void => {
    const bounds = this.overlay.getBoundingClientRect();
    for (const label of this.overlay.querySelectorAll<HTMLElement>('.oceano-compare-label')) {
      label.style.translate = '';
      const r = label.getBoundingClientRect();
      const shift = r.left < bounds.left ? bounds.left - r.left : r.right > bounds.right ? bounds.right - r.right : 0;
      if (shift !== 0) label.style.translate = `${shift}px 0`;
    }
  };

  private build(compare: string): void {
    for (const divider of this.dividers) divider.remove();
    this.compare = compare;
    const names = compareModelNames<string>(compare);
    this.dividers = names.slice(1).map((right, i) => this.makeDivider(i, names[i], right));
    this.overlay.hidden = this.dividers.length === 0;
  }

  private makeDivider(index: number, left: string, right: string): HTMLElement {
    const divider = document.createElement('div');
    divider.className = 'oceano-compare-divider';
    divider.tabIndex = 0;
    divider.setAttribute('role', 'separator');
    divider.setAttribute('aria-orientation', 'vertical');
    divider.setAttribute('aria-valuemin', '0');
    divider.setAttribute('aria-valuemax', '100');
    divider.setAttribute('aria-label', this.tr.ui('compareDivider'));
    divider.dataset.split = SPLIT_KEYS[index];
    // Each strip named once: the first divider names both its sides, a second only its right.
    const labels =
      index === 0
        ? ([
            ['left', left],
            ['right', right],
          ] as const)
        : ([['right', right]] as const);
    for (const [side, name] of labels) {
      const label = document.createElement('span');
      label.className = `oceano-compare-label oceano-compare-label-${side}`;
      label.textContent = name;
      divider.appendChild(label);
    }
    divider.addEventListener('pointerdown', (event) => {
      event.preventDefault();
      divider.setPointerCapture(event.pointerId);
      divider.focus();
    });
    divider.addEventListener('pointermove', (event) => {
      if (!divider.hasPointerCapture(event.pointerId)) return;
      const rect = this.overlay.getBoundingClientRect();
      if (rect.width > 0) this.move(index, (event.clientX - rect.left) / rect.width);
    });
    divider.addEventListener('keydown', (event) => {
      const f = this.shown[index];
      const to: Record<string, number> = {
        ArrowLeft: f - KEY_STEP,
        ArrowRight: f + KEY_STEP,
        PageDown: f - PAGE_STEP,
        PageUp: f + PAGE_STEP,
        Home: 0,
        End: 1,
      };
      if (!(event.key in to)) return;
      // The arrows also steer the boat (boatSteering.ts): a focused divider keeps them.
      event.preventDefault();
      event.stopPropagation();
      this.move(index, to[event.key]);
    });
    this.overlay.appendChild(divider);
    return divider;
  }

  /** A divider stays between its neighbours: the first left of the second, the second right of the first. */
  private move(index: number, f: number): void {
    const low = index > 0 ? this.shown[index - 1] : 0;
    const high = index + 1 < this.shown.length ? this.shown[index + 1] : 1;
    this.setSplit(SPLIT_KEYS[index], onStep(Math.min(high, Math.max(low, f))));
  }

  dispose(): void {
    this.container.removeEventListener(FREE_AREA_EVENT, this.keepLabelsInside);
    this.overlay.remove();
  }
}
