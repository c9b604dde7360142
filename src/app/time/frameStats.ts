import { median } from '../../sim/physics/sampleStatistics';
import type { RenderStats } from '../../render/ocean/oceanView';
import type { TwinStatus } from '../../sim/waves/fft/twinStatus';

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
  /**
   * Mean main-thread time per frame of the wave model's CPU twin, where the model measures it
   * (waves=fft: the surface questions of the boat and the underwater switch, the Worker
   * requests and receiving its fields), ms; null for other models. A mean, not a median: the
   * parts are microseconds each, timed with a clock coarsened to 0.1 ms, whose jittered
   * readings are right on average only.
   */
  twinMs: number | null;
  /** How much data the wave model's CPU twin has had from its Worker, and of which time; null for models without one. */
  twin: TwinStatus | null;
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
  private readonly twinTimes: number[] = [];
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

  /** The wave model's CPU twin's main-thread ms since the last frame; null where the model does not measure it. */
  recordTwin(ms: number | null): void {
    if (ms === null) this.twinTimes.length = 0;
    else keep(this.twinTimes, ms);
  }

  /** A frame whose GPU work was waited for: from its start to the end of the wait, ms. */
  recordSyncedFrame(ms: number): void {
    keep(this.frameTimes, ms);
  }

  /** performance.now() counts from the navigation start, so this is the time to first frame. */
  markFirstFrame(): void {
    this.firstFrameAt ??= performance.now();
  }

  summary(render: RenderStats, twin: TwinStatus | null): OceanStats {
    this.timingWanted = true;
    const med = (samples: number[]) => (samples.length ? median(samples) : 0);
    const twinMs = this.twinTimes.length ? this.twinTimes.reduce((a, b) => a + b, 0) / this.twinTimes.length : null;
    return {
      frameMs: med(this.frameTimes),
      cpuMs: med(this.updateTimes),
      boatMs: med(this.boatTimes),
      twinMs,
      twin,
      ...render,
      ttffMs: this.firstFrameAt,
    };
  }
}
