/** A figure that may hold one WebGL context. */
export interface BudgetedFigure {
  /** Pixels between the figure and the viewport (0 when on screen). */
  distanceToViewport(): number;
  /** Gives its context back now, or as soon as it has finished starting. */
  releaseForBudget(): void;
  /** A context became free: try starting again. */
  retry(): void;
}

/**
 * How many figures of one page may hold a WebGL context at once. Browsers keep only a few
 * alive (Chromium 16) and take the oldest away without asking; this hands them out first,
 * taking one back from the figure farthest from the screen when a nearer one needs it.
 */
export class ContextBudget {
  private readonly live = new Set<BudgetedFigure>();
  private readonly waiting = new Set<BudgetedFigure>();

  constructor(public limit: number) {}

  get held(): number {
    return this.live.size;
  }

  /** Whether the figure may take a context now; if not, it is retried when one comes free. */
  claim(figure: BudgetedFigure): boolean {
    if (this.live.has(figure)) return true;
    if (this.live.size >= this.limit) {
      const farthest = farthestOf(this.live);
      if (farthest && farthest.distanceToViewport() > figure.distanceToViewport()) farthest.releaseForBudget();
    }
    if (this.live.size < this.limit) {
      this.waiting.delete(figure);
      this.live.add(figure);
      return true;
    }
    this.waiting.add(figure);
    return false;
  }

  /** The figure holds no context any more (released or removed). */
  free(figure: BudgetedFigure): void {
    this.waiting.delete(figure);
    if (!this.live.delete(figure)) return;
    let nearest: BudgetedFigure | undefined;
    for (const candidate of this.waiting)
      if (!nearest || candidate.distanceToViewport() < nearest.distanceToViewport()) nearest = candidate;
    nearest?.retry();
  }
}

function farthestOf(figures: Set<BudgetedFigure>): BudgetedFigure | undefined {
  let farthest: BudgetedFigure | undefined;
  for (const figure of figures) if (!farthest || figure.distanceToViewport() > farthest.distanceToViewport()) farthest = figure;
  return farthest;
}

/** Pixels between an element's box and the viewport, vertically or sideways. */
export function distanceToViewport(element: Element): number {
  const box = element.getBoundingClientRect();
  const dy = box.bottom < 0 ? -box.bottom : box.top > innerHeight ? box.top - innerHeight : 0;
  const dx = box.right < 0 ? -box.right : box.left > innerWidth ? box.left - innerWidth : 0;
  return Math.hypot(dx, dy);
}
