/**
 * The one clock of the simulation. The frame loop advances it with real elapsed time
 * while playing; everything below the app receives its time from here.
 */
export class SimulationClock {
  /** Longest step taken in one frame, so a tab coming back from the background does not jump. */
  static readonly MAX_STEP = 0.1;

  constructor(
    public time = 0,
    public playing = true,
  ) {}

  advance(realSeconds: number): void {
    if (this.playing) this.time += Math.min(Math.max(realSeconds, 0), SimulationClock.MAX_STEP);
  }

  setTime(seconds: number): void {
    this.time = seconds;
  }
}
