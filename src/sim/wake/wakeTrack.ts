/**
 * The boat's recent track, the memory the Kelvin wake is made from (src/sim/wake/kelvinWake.ts).
 *
 * A ring buffer of the boat's position and speed at the fixed instants k·interval. A frame
 * rarely lands on such an instant, so the sample is interpolated linearly between the
 * previous frame and this one: the recorded track is the same whatever the frame rate, and
 * a reload that replays the same motion records the same track (deterministic given the
 * boat's motion). Besides the samples it keeps the head, the boat's latest position, so the
 * wake starts exactly at the hull.
 *
 * A step back in time, or a jump longer than `maxGap` (setTime, a paused tab), starts a
 * fresh track: the boat did not sail that gap, so it must leave no wake across it.
 */

/**
 * Two rates. The last 16 s are kept every 0.5 s (at the top speed, 12 m/s, a 6 m chord, under
 * a hull length, so a turn near the boat is followed closely); older track every 2 s. The
 * wake integral needs fine steps only where the waves are young: the stationary-phase
 * width of the τ-integral grows like √(4π x / g) with the distance x behind the boat (3.6 s
 * at 10 m, 8 s at 50 m), so 2 s steps lose nothing far back and buy ≈ 78 s of history,
 * enough for the wedge to form over 10–14 wavelengths at 3.5–4.5 m/s (see kelvinWake.ts).
 */
export const TRACK_INTERVAL = 0.5;
export const TRACK_FINE_SAMPLES = 32;
export const TRACK_COARSE_INTERVAL = 2;
export const TRACK_COARSE_SAMPLES = 40;
/**
 * Points the wake integrates over, head included. It is also the length of the GLSL
 * uniform array (shaders/wake.glsl) and so the number of sources a vertex near the boat
 * evaluates.
 */
export const TRACK_POINTS = 64;
/** A frame gap longer than this, seconds, is a jump, not sailing: the track restarts. */
export const TRACK_MAX_GAP = 1;

export interface TrackPoint {
  x: number;
  z: number;
  /** Seconds, the clock the boat's motion runs on. */
  time: number;
  /** Boat speed there, m/s (signed: negative astern). */
  speed: number;
}

/** What a share link needs to rebuild the track exactly. */
export interface TrackState {
  interval: number;
  /** Oldest first, at consecutive multiples of `interval`. */
  samples: TrackPoint[];
  head: TrackPoint | null;
}

export class TrackRecorder {
  /** Ring buffer, 4 numbers per sample: x, z, time, speed. */
  private readonly buffer: Float64Array;
  private count = 0;
  /** Index of the next write. */
  private next = 0;
  private head: TrackPoint | null = null;

  constructor(
    readonly interval = TRACK_INTERVAL,
    readonly capacity = TRACK_FINE_SAMPLES,
    private readonly maxGap = TRACK_MAX_GAP,
  ) {
    if (!(interval > 0) || !Number.isInteger(capacity) || capacity < 1)
      throw new Error('TrackRecorder needs interval > 0 and capacity ≥ 1.');
    this.buffer = new Float64Array(capacity * 4);
  }

  /** Records the boat at `time`; call once per frame with the boat's position then. */
  record(time: number, x: number, z: number, speed: number): void {
    const prev = this.head;
    if (prev === null || !(time >= prev.time) || time - prev.time > this.maxGap) {
      this.reset();
      this.head = { x, z, time, speed };
      // A track starting exactly on an instant records it, so replays agree.
      if (isInstant(time, this.interval)) this.push(this.head);
      return;
    }
    // Every instant k·interval in (prev.time, time], interpolated on the frame's straight step.
    const first = Math.floor(prev.time / this.interval) + 1;
    const last = Math.floor(time / this.interval);
    for (let k = first; k <= last; k++) {
      const t = k * this.interval;
      const f = time > prev.time ? (t - prev.time) / (time - prev.time) : 1;
      this.push({
        x: prev.x + (x - prev.x) * f,
        z: prev.z + (z - prev.z) * f,
        time: t,
        speed: prev.speed + (speed - prev.speed) * f,
      });
    }
    this.head = { x, z, time, speed };
  }

  reset(): void {
    this.count = 0;
    this.next = 0;
    this.head = null;
  }

  /** The boat's latest recorded position, or null before the first record. */
  latest(): TrackPoint | null {
    return this.head;
  }

  /**
   * Newest first: the head, then the samples back in time, at most `TRACK_POINTS` in all
   * (the head is not repeated when it sits exactly on the newest sample).
   */
  points(): TrackPoint[] {
    if (this.head === null) return [];
    const out: TrackPoint[] = [{ ...this.head }];
    for (let i = 0; i < this.count; i++) {
      const p = this.sample(this.count - 1 - i);
      if (i === 0 && p.time === this.head.time) continue;
      out.push(p);
    }
    return out;
  }

  state(): TrackState {
    const samples: TrackPoint[] = [];
    for (let i = 0; i < this.count; i++) samples.push(this.sample(i));
    return { interval: this.interval, samples, head: this.head ? { ...this.head } : null };
  }

  /** Rebuilds a recorder from `state()`; throws on a state that could not have been recorded. */
  static fromState(state: TrackState, capacity = TRACK_FINE_SAMPLES): TrackRecorder {
    const recorder = new TrackRecorder(state.interval, capacity);
    const samples = state.samples.slice(-capacity);
    for (let i = 0; i < samples.length; i++) {
      const s = samples[i];
      if (![s.x, s.z, s.time, s.speed].every(Number.isFinite)) throw new Error('Track sample is not finite.');
      if (i > 0 && Math.abs(s.time - samples[i - 1].time - state.interval) > 1e-6)
        throw new Error('Track samples are not one interval apart.');
      recorder.push(s);
    }
    if (state.head) {
      const h = state.head;
      if (![h.x, h.z, h.time, h.speed].every(Number.isFinite)) throw new Error('Track head is not finite.');
      const newest = samples[samples.length - 1];
      if (newest && (h.time < newest.time || h.time - newest.time >= state.interval + 1e-6))
        throw new Error('Track head does not follow its samples.');
      recorder.head = { ...h };
    } else if (samples.length > 0) {
      throw new Error('A track with samples needs a head.');
    }
    return recorder;
  }

  private push(p: TrackPoint): void {
    const o = this.next * 4;
    this.buffer[o] = p.x;
    this.buffer[o + 1] = p.z;
    this.buffer[o + 2] = p.time;
    this.buffer[o + 3] = p.speed;
    this.next = (this.next + 1) % this.capacity;
    this.count = Math.min(this.count + 1, this.capacity);
  }

  /** The i-th sample, oldest = 0. */
  private sample(i: number): TrackPoint {
    const index = (this.next - this.count + i + this.capacity) % this.capacity;
    const o = index * 4;
    return { x: this.buffer[o], z: this.buffer[o + 1], time: this.buffer[o + 2], speed: this.buffer[o + 3] };
  }
}

/**
 * The track the wake reads: a fine recorder for the recent past and a coarse one behind it
 * (see TRACK_INTERVAL). Both record every frame; `points()` joins them.
 */
export class WakeTrack {
  constructor(
    readonly fine = new TrackRecorder(TRACK_INTERVAL, TRACK_FINE_SAMPLES),
    readonly coarse = new TrackRecorder(TRACK_COARSE_INTERVAL, TRACK_COARSE_SAMPLES),
  ) {}

  record(time: number, x: number, z: number, speed: number): void {
    this.fine.record(time, x, z, speed);
    this.coarse.record(time, x, z, speed);
  }

  reset(): void {
    this.fine.reset();
    this.coarse.reset();
  }

  /** Newest first: head, fine samples, then coarse samples older than the oldest fine one; at most TRACK_POINTS. */
  points(): TrackPoint[] {
    const out = this.fine.points();
    const oldest = out.length > 0 ? out[out.length - 1].time : Infinity;
    for (const p of this.coarse.points().slice(1)) {
      if (out.length >= TRACK_POINTS) break;
      if (p.time < oldest) out.push(p);
    }
    return out;
  }

  state(): { fine: TrackState; coarse: TrackState } {
    return { fine: this.fine.state(), coarse: this.coarse.state() };
  }

  static fromState(state: { fine: TrackState; coarse: TrackState }): WakeTrack {
    return new WakeTrack(
      TrackRecorder.fromState(state.fine, TRACK_FINE_SAMPLES),
      TrackRecorder.fromState(state.coarse, TRACK_COARSE_SAMPLES),
    );
  }

  /** Share-link text: the two recorders' texts joined by "~". */
  serialize(): string {
    return `${serializeTrack(this.fine.state())}~${serializeTrack(this.coarse.state())}`;
  }

  static parse(text: string): WakeTrack {
    const [fine, coarse] = text.split('~');
    if (coarse === undefined) throw new Error('Wake track text needs two parts joined by "~".');
    return WakeTrack.fromState({ fine: parseTrack(fine), coarse: parseTrack(coarse) });
  }
}

function isInstant(time: number, interval: number): boolean {
  return Math.abs(time / interval - Math.round(time / interval)) < 1e-9;
}

/**
 * Share-link text for a track: every number written to read back bit for bit (a reopened link
 * draws the very same wake, pixel for pixel; rounding positions to the centimetre moved
 * 0.25 % of a 320×180 picture's pixels by up to 21 levels), samples' times implied by the
 * interval. "i;t0;x,z,s;x,z,s;...|hx,hz,hs,ht".
 */
export function serializeTrack(state: TrackState): string {
  const r2 = (v: number) => String(v);
  const t0 = state.samples.length > 0 ? Math.round(state.samples[0].time / state.interval) : 0;
  const samples = state.samples.map((s) => `${r2(s.x)},${r2(s.z)},${r2(s.speed)}`).join(';');
  const h = state.head;
  const head = h ? `${r2(h.x)},${r2(h.z)},${r2(h.speed)},${String(h.time)}` : '';
  return `${state.interval};${t0};${samples}|${head}`;
}

/** Inverse of serializeTrack; throws on malformed text. */
export function parseTrack(text: string): TrackState {
  const [body, headText] = text.split('|');
  if (headText === undefined) throw new Error('Track text lacks its head.');
  const parts = body.split(';');
  const interval = Number(parts[0]);
  const t0 = Number(parts[1]);
  if (!(interval > 0) || !Number.isInteger(t0)) throw new Error('Track text has a bad interval or start.');
  const numbers = (s: string, n: number) => {
    const v = s.split(',').map(Number);
    if (v.length !== n || !v.every(Number.isFinite)) throw new Error(`Bad track entry "${s}".`);
    return v;
  };
  const samples = parts
    .slice(2)
    .filter((s) => s !== '')
    .map((s, i) => {
      const [x, z, speed] = numbers(s, 3);
      return { x, z, speed, time: (t0 + i) * interval };
    });
  let head: TrackPoint | null = null;
  if (headText !== '') {
    const [x, z, speed, time] = numbers(headText, 4);
    head = { x, z, speed, time };
  }
  return { interval, samples, head };
}
