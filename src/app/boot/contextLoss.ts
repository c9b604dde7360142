/**
 * Follows the canvas's WebGL context: `lost` when the browser takes it (too many contexts,
 * a GPU reset), `restored` when it gives it back; three.js re-creates its GL state then and
 * uploads every geometry, texture and program again on the next render. While it is lost
 * a notice says so and no frame is drawn.
 */
export class ContextWatch {
  private notice: HTMLElement | null = null;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly hooks: { showNotice(): HTMLElement; removeNotice(notice: HTMLElement): void; setLost(lost: boolean): void; redraw(): void },
  ) {
    canvas.addEventListener('webglcontextlost', this.onLost);
    canvas.addEventListener('webglcontextrestored', this.onRestored);
  }

  get lost(): boolean {
    return this.notice !== null;
  }

  private readonly onLost = (): void => {
    this.notice ??= this.hooks.showNotice();
    this.hooks.setLost(true);
  };

  private readonly onRestored = (): void => {
    if (this.notice) this.hooks.removeNotice(this.notice);
    this.notice = null;
    this.hooks.setLost(false);
    this.hooks.redraw();
  };

  dispose(): void {
    this.canvas.removeEventListener('webglcontextlost', this.onLost);
    this.canvas.removeEventListener('webglcontextrestored', this.onRestored);
  }
}
