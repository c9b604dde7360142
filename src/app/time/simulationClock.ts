/**
 * The one clock of the simulation. The frame loop advances it with real elapsed time
 * while playing; everything below the app receives its time from here.
 */
export class SimulationClock {
  /** Longest step taken in one frame, so a tab coming back from the background does not jump. */
  static readonly MAX_STEP = 0.1;
  /** One frame at 60 fps: what Step advances, times the time scale, as a played frame does. */
  static readonly FRAME = 1 / 60;

  constructor(
    public time = 0,
    public playing = true,
  ) {}

  /** `scale`: simulated seconds per real second (slow motion below 1). */
  advance(realSeconds: number, scale = 1): void {
    if (this.playing) this.time += Math.min(Math.max(realSeconds, 0), SimulationClock.MAX_STEP) * scale;
  }

  /** One frame of 1/60 s, played or paused: what a 60 fps loop adds per frame. */
  step(scale = 1): void {
    this.time += SimulationClock.FRAME * scale;
  }

  setTime(seconds: number): void {
    this.time = seconds;
  }
}
