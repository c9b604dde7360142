import { median } from '../sim/sampleStatistics';
import type { RenderStats } from '../render/oceanView';

/** Frames kept for each median. */
const FRAME_SAMPLES = 30;
/** While frame times are wanted, how often a looped frame waits for the GPU to be measured (frames). */
const SYNC_EVERY = 8;

export interface OceanStats extends RenderStats {
  /** Median wall time of recent GPU-synced frames, update and draw together (ms). */
  frameMs: number;
  /** Median JavaScript time of recent frames' update step, before any draw call (ms). */
  cpuMs: number;
  /** Median CPU time of the boat's share of the update step (five surface samples, damping, pose), ms. */
  boatMs: number;
  /** Time to first frame: navigation start to the first frame drawn and synced (ms); null before it. */
  ttffMs: number | null;
}

function keep(samples: number[], value: number): void {
  samples.push(value);
  if (samples.length > FRAME_SAMPLES) samples.shift();
}

/**
 * Rolling frame timings. Measuring a frame's full cost means waiting for the GPU (a
 * one-pixel read), which stalls the pipeline; the shipped loop does that only once someone
 * has asked for stats(), and then on one frame in SYNC_EVERY.
 */
export class FrameStats {
  private readonly frameTimes: number[] = [];
  private readonly updateTimes: number[] = [];
  private readonly boatTimes: number[] = [];
  private firstFrameAt: number | null = null;
  private timingWanted = false;
  framesDrawn = 0;

  /** Whether the loop's next frame should wait for the GPU. */
  loopShouldSync(): boolean {
    return this.timingWanted && this.framesDrawn % SYNC_EVERY === 0;
  }

  /** The CPU half of a frame: the boat's update and the whole update step, ms. */
  recordUpdate(boatMs: number, updateMs: number): void {
    keep(this.boatTimes, boatMs);
    keep(this.updateTimes, updateMs);
  }

  /** A frame whose GPU work was waited for: from its start to the end of the wait, ms. */
  recordSyncedFrame(ms: number): void {
    keep(this.frameTimes, ms);
  }

  /** performance.now() counts from the navigation start, so this is the time to first frame. */
  markFirstFrame(): void {
    this.firstFrameAt ??= performance.now();
  }

  summary(render: RenderStats): OceanStats {
    this.timingWanted = true;
    const med = (samples: number[]) => (samples.length ? median(samples) : 0);
    return { frameMs: med(this.frameTimes), cpuMs: med(this.updateTimes), boatMs: med(this.boatTimes), ...render, ttffMs: this.firstFrameAt };
  }
}
