/** Why the frame loop is stopped although the app is alive. */
export type SuspendReason = 'hidden' | 'offscreen';
/** What else stops it: the GL context is gone until the browser restores it. */
type StopReason = SuspendReason | 'contextLost';

export interface LoopActivity {
  looping: boolean;
  framesDrawn: number;
}

export interface FrameLoopHooks {
  /** One animation frame of a running loop: `seconds` since the previous one (0 on the first). */
  tick(seconds: number): void;
  /** One frame for a paused view whose camera, size or parameters changed. */
  redraw(): void;
  /** Whether the simulation clock is running. */
  playing(): boolean;
}

/**
 * Runs requestAnimationFrame exactly when the app is started, playing, visible, on screen
 * and has a GL context. A paused view draws only when something changes (requestRender),
 * so a page of frozen figures costs nothing between interactions.
 */
export class FrameLoop {
  private looping = false;
  private running = false;
  private handle = 0;
  private pending = 0;
  private lastFrameTime: number | null = null;
  private readonly stopped = new Set<StopReason>();

  constructor(private readonly hooks: FrameLoopHooks) {}

  get isLooping(): boolean {
    return this.looping;
  }

  /** The app is built and may draw: from now on the loop follows its conditions. */
  start(): void {
    this.running = true;
    this.refresh();
  }

  dispose(): void {
    this.running = false;
    this.refresh();
    cancelAnimationFrame(this.handle);
    cancelAnimationFrame(this.pending);
  }

  setStopped(reason: StopReason, stopped: boolean): void {
    if (stopped) this.stopped.add(reason);
    else this.stopped.delete(reason);
    this.refresh();
  }

  /** Starts or stops the loop to match the conditions (call after play or pause). */
  refresh(): void {
    const shouldRun = this.running && this.stopped.size === 0 && this.hooks.playing();
    if (shouldRun === this.looping) return;
    this.looping = shouldRun;
    if (shouldRun) {
      // Time off screen is not simulated: the sea resumes where it stopped.
      this.lastFrameTime = null;
      this.handle = requestAnimationFrame(this.loop);
    } else {
      cancelAnimationFrame(this.handle);
    }
  }

  /** One frame on the next animation frame, unless the loop will draw one anyway. */
  readonly requestRender = (): void => {
    if (this.looping || this.pending !== 0 || !this.running) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = 0;
      this.hooks.redraw();
    });
  };

  private readonly loop = (now: number): void => {
    const seconds = this.lastFrameTime === null ? 0 : (now - this.lastFrameTime) / 1000;
    this.lastFrameTime = now;
    this.hooks.tick(seconds);
    this.handle = requestAnimationFrame(this.loop);
  };
}
