import type { HeightRecord } from './probeStatistics';

/** How much simulation time the probe keeps, seconds. */
export const PROBE_WINDOW = 30;

/**
 * The probe's record: η at one point, one sample per drawn frame at the clock's time, the
 * last PROBE_WINDOW seconds of simulation time kept. It follows the simulation clock, not the
 * wall clock: paused, nothing is added (a redraw at the same time is not a new sample); each
 * Step adds one; slow motion samples more densely. A jump back in time starts it afresh, since
 * what it held is then the future.
 */
export class ProbeRecord {
  private times: number[] = [];
  private heights: number[] = [];

  /** Adds the sample at `time`; returns false when it was a repeat of the last time. */
  add(time: number, height: number): boolean {
    const last = this.times.length > 0 ? this.times[this.times.length - 1] : -Infinity;
    if (time === last) return false;
    if (time < last) this.clear();
    this.times.push(time);
    this.heights.push(height);
    let old = 0;
    while (this.times[old] < time - PROBE_WINDOW) old++;
    this.times.splice(0, old);
    this.heights.splice(0, old);
    return true;
  }

  clear(): void {
    this.times = [];
    this.heights = [];
  }

  /** The samples of the last PROBE_WINDOW seconds, oldest first. */
  window(): HeightRecord & { times: number[]; heights: number[] } {
    return { times: [...this.times], heights: [...this.heights] };
  }
}
