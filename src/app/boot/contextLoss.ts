import type { WebGLRenderer } from 'three';

/**
 * Follows the canvas's WebGL context: `lost` when the browser takes it (too many contexts,
 * a GPU reset), `restored` when it gives it back; three.js re-creates its GL state then and
 * uploads every geometry, texture and program again on the next render. While it is lost
 * a notice says so and no frame is drawn.
 */
export class ContextWatch {
  private notice: HTMLElement | null = null;
  private readonly canvas: HTMLCanvasElement;

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly hooks: {
      showNotice(): HTMLElement;
      removeNotice(notice: HTMLElement): void;
      setLost(lost: boolean): void;
      redraw(): void;
    },
  ) {
    this.canvas = renderer.domElement;
    // After three.js's own listeners (added when the renderer was made): a restored frame is drawn once its state is new.
    this.canvas.addEventListener('webglcontextlost', this.onLost);
    this.canvas.addEventListener('webglcontextrestored', this.onRestored);
  }

  get lost(): boolean {
    return this.notice !== null;
  }

  private readonly onLost = (): void => {
    this.notice ??= this.hooks.showNotice();
    this.hooks.setLost(true);
    releaseRendererState(this.renderer);
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

/**
 * three.js, on a restored context, makes its texture, geometry, program and state managers
 * anew without disposing the old ones. Each texture, render target and geometry it ever drew
 * keeps a 'dispose' listener of the old managers, and through it the old managers themselves
 * (their property maps, programs and GL state): every restore would leak a renderer's worth of
 * bookkeeping. Disposing the renderer while the context is lost removes those listeners (its
 * GL deletes on a lost context do nothing). Renderer.dispose() also unhooks three's own
 * context listeners from the canvas, which must stay for its restore to rebuild the renderer:
 * those removals are skipped.
 */
export function releaseRendererState(renderer: WebGLRenderer): void {
  const canvas = renderer.domElement;
  const remove = canvas.removeEventListener;
  canvas.removeEventListener = (type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions) => {
    if (!type.startsWith('webglcontext')) remove.call(canvas, type, listener, options);
  };
  try {
    renderer.dispose();
  } finally {
    Reflect.deleteProperty(canvas, 'removeEventListener');
  }
}
