import type { LiveWaveModel, SurfaceSample } from './waveModel';

/**
 * Heights and normals for many points at once: a scene's floating bodies (buoys, crates,
 * debris) each ask the sea where its surface is, every frame.
 *
 * Layout, flat and typed so a thousand points cost no objects:
 *   points: [x0, z0, x1, z1, …]          world x and z of each point, metres
 *   out:    [h0, nx0, ny0, nz0, h1, …]    per point its surface height (metres, world y) and
 *                                         the unit normal there (x, y, z), 4 numbers per point
 * so point i's height is out[4i] and its normal out[4i + 1 … 4i + 3].
 */
export const SAMPLE_FLOATS = 4;

/** What sampleSurfaces takes as points: x, z pairs. */
export type SurfacePoints = Float32Array | Float64Array | readonly number[];
/** What it writes: 4 numbers per point (SAMPLE_FLOATS). */
export type SurfaceSamples = Float32Array | Float64Array;

/** How sampleSurfaces answers (the third argument of Ocean.sampleSurfaces). */
export interface SampleSurfacesOptions {
  /**
   * The time (seconds) to answer for, exactly: the CPU twin's fields are computed for it if they
   * are not held (on the FFT sea, milliseconds). Left out: the last frame's sea, from the data
   * the frame already holds, nothing recomputed (what the app's boat rides).
   */
  time?: number;
}

/** The options checked: a TypeError for a key it does not know or a time that is not a finite number. */
export function checkSampleOptions(options: unknown): SampleSurfacesOptions {
  if (options === undefined) return {};
  if (typeof options !== 'object' || options === null) {
    throw new TypeError(`sampleSurfaces takes its options as an object ({ time }), got ${describe(options)}.`);
  }
  for (const [key, value] of Object.entries(options)) {
    if (key !== 'time') throw new TypeError(`sampleSurfaces has no option "${key}"; its only option is time (seconds).`);
    if (value !== undefined && (typeof value !== 'number' || !Number.isFinite(value))) {
      throw new TypeError(`sampleSurfaces needs time as a finite number of seconds, got ${describe(value)}.`);
    }
  }
  return options as SampleSurfacesOptions;
}

/** `out` for `points`, checked (a TypeError that says what was wanted), or a new Float32Array of the right length. */
export function checkSurfaceBatch(points: unknown, out: unknown): SurfaceSamples {
  const typed = points instanceof Float32Array || points instanceof Float64Array;
  if (!typed && !Array.isArray(points)) {
    throw new TypeError(
      `sampleSurfaces needs points as a Float32Array, Float64Array or array of x, z pairs (metres), got ${describe(points)}.`,
    );
  }
  const list = points as ArrayLike<unknown>;
  if (list.length % 2 !== 0) throw new TypeError(`sampleSurfaces needs x, z pairs: an even number of coordinates, got ${list.length}.`);
  for (let i = 0; i < list.length; i++) {
    const v = list[i];
    if (typeof v !== 'number' || !Number.isFinite(v)) {
      throw new TypeError(`sampleSurfaces needs finite coordinates: point ${i >> 1}'s ${i % 2 === 0 ? 'x' : 'z'} is ${String(v)}.`);
    }
  }
  const wanted = (list.length / 2) * SAMPLE_FLOATS;
  if (out === undefined) return new Float32Array(wanted);
  if (!(out instanceof Float32Array || out instanceof Float64Array)) {
    throw new TypeError(
      `sampleSurfaces writes into a Float32Array or Float64Array (4 numbers per point: height, nx, ny, nz), got ${describe(out)}.`,
    );
  }
  if (out.length !== wanted) {
    throw new TypeError(`sampleSurfaces needs out of length ${wanted} (4 per point for ${list.length / 2} points), got ${out.length}.`);
  }
  return out;
}

/**
 * Each point's surface sample at `time`, into `out` (see SAMPLE_FLOATS for the layout), each
 * equal to `adjust(model.sample(x, z, time), x, z)`: the model's own batch where it has one and
 * nothing adjusts (the FFT sea's, allocation-free), one call per point otherwise. `adjust`: what
 * the caller adds to each sample (the interactive waves), or null.
 */
export function sampleSurfaces(
  model: LiveWaveModel,
  points: SurfacePoints,
  time: number,
  out: SurfaceSamples,
  adjust: ((sample: SurfaceSample, x: number, z: number) => SurfaceSample) | null = null,
): SurfaceSamples {
  if (model.sampleMany && !adjust) {
    model.sampleMany(points, time, out);
    return out;
  }
  const count = points.length >> 1;
  for (let i = 0; i < count; i++) {
    const x = points[2 * i];
    const z = points[2 * i + 1];
    const raw = model.sample(x, z, time);
    const s = adjust ? adjust(raw, x, z) : raw;
    out[SAMPLE_FLOATS * i] = s.height;
    out[SAMPLE_FLOATS * i + 1] = s.normal[0];
    out[SAMPLE_FLOATS * i + 2] = s.normal[1];
    out[SAMPLE_FLOATS * i + 3] = s.normal[2];
  }
  return out;
}

function describe(value: unknown): string {
  if (value === null) return 'null';
  if (typeof value === 'object') return (value as object).constructor?.name ?? 'an object';
  return `${typeof value} ${String(value)}`;
}
