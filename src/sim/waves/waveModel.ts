import type { Heightmap } from '../noise/perlinNoise';
import type { OceanParams } from '../params/params';
import type { TwinStatus } from './fft/twinStatus';

/**
 * The seam every wave model plugs into, CPU side. A model's GLSL displacement chunk
 * (shaders/) and this TypeScript twin describe the same surface; a GPU read-back parity
 * test holds them together. The boat, the underwater switch, caustics and the physics
 * panel only ever see this interface.
 */
export type WaveModelName = 'seed' | 'fft' | 'gerstner';

export interface SurfaceSample {
  /** Height of the surface above the world point, metres. */
  height: number;
  /** Unit normal of the surface there. */
  normal: [number, number, number];
}

export interface DisplacementBounds {
  /** Largest |dy| the model can produce, metres. */
  vertical: number;
  /** Largest horizontal |(dx, dz)| the model can produce, metres. */
  horizontal: number;
}

export interface WaveModel {
  readonly name: WaveModelName;
  /**
   * Where the undisplaced grid point (x, 0, z) goes at `time`: [dx, dy, dz], metres. This is
   * exactly what the vertex shader adds to a grid vertex.
   */
  displacement(x: number, z: number, time: number): [number, number, number];
  /** Height and normal of the displaced surface above the world point (x, z). */
  sample(x: number, z: number, time: number): SurfaceSample;
  /** Culling bounds: a chunk's box is grown by these so no displaced vertex leaves it. */
  bounds(): DisplacementBounds;
}

/** Fixed-point steps used by default; choppy seas converge in 3–4 (tests measure the residual). */
export const INVERSION_STEPS = 4;

/**
 * The grid point whose displaced position lands above the world point (x, z): solve
 * p + D(p) = q for p by the fixed-point iteration p ← q − D(p), which converges while the
 * horizontal displacement's Jacobian has norm below 1 (crests that do not loop). At most
 * `steps` steps; it stops sooner once a step moves p by `tolerance` metres or less in x and
 * in z (0: only when p stops moving, which changes nothing). Returns the grid point [px, pz]
 * and the residual distance |p + D(p) − q| in metres.
 */
export function undoHorizontalDisplacement(
  displacement: (x: number, z: number) => [number, number, number],
  x: number,
  z: number,
  steps = INVERSION_STEPS,
  tolerance = 0,
): { x: number; z: number; residual: number } {
  let px = x;
  let pz = z;
  for (let i = 0; i < steps; i++) {
    const d = displacement(px, pz);
    const nx = x - d[0];
    const nz = z - d[2];
    const settled = Math.abs(nx - px) <= tolerance && Math.abs(nz - pz) <= tolerance;
    px = nx;
    pz = nz;
    if (settled) break;
  }
  const d = displacement(px, pz);
  return { x: px, z: pz, residual: Math.hypot(px + d[0] - x, pz + d[2] - z) };
}

/** The `waves` parameter's values: one per registered model. */
export type WavesChoice = OceanParams['waves'];

/**
 * A wave model the app can run: the WaveModel seam plus what a live page needs of it. The
 * model keeps the parameters it is given and reads only those it uses.
 */
export interface LiveWaveModel extends WaveModel {
  readonly name: WavesChoice;
  /** Takes the current parameters; returns true when data the GPU holds (textures) must be made again. */
  setParams(params: OceanParams): boolean;
  /** Height of the displaced surface above the world point (x, z), metres. */
  height(x: number, z: number, time: number): number;
  /**
   * Changes whenever the surface the model answers with may change for any reason but the
   * time asked: its parameters, or data it reads (the FFT twin's fields, computed here or
   * delivered by its Worker). Equal revisions of one model: height(x, z, t) gives the same
   * answer for the same (x, z, t), so a caller may keep it (the boat's pose on a paused view).
   */
  readonly surfaceRevision: number;
  /**
   * Where the model times its CPU twin's work on the calling thread: the ms spent since the
   * last call, counting afresh (FftWaveModel, whose twin must stay cheap on the main thread).
   */
  takeMainThreadMs?(): number;
  /** Where the model's CPU twin gets its data from a Worker: how much has arrived, and of which time (FftWaveModel). */
  twinStatus?(): TwinStatus;
  /**
   * The mean-square slope (both horizontal directions summed) of the surface the model draws
   * at `time`: the slopes its normals resolve at full resolution. What Cox & Munk's σ² holds
   * beyond it is the glint's roughness (src/sim/optics/resolvedSlopes.ts).
   */
  slopeVariance(time: number): number;
  /**
   * sample() for many points at one time, where the model has a faster way than one call per
   * point: points[2i], points[2i + 1] are world x, z (m); out[4i..4i+3] gets [height, nx, ny, nz],
   * each exactly what sample() answers (src/sim/waves/surfaceBatch.ts).
   */
  sampleMany?(points: ArrayLike<number>, time: number, out: { [i: number]: number }): void;
  /**
   * The time whose data answers a question about the frame at `time` with nothing recomputed:
   * what height() reads (the FFT twin's newest fields while the clock plays with a Worker, a
   * frame or two behind). A model whose answers cost the same at any time omits it: `time`.
   */
  frameDataTime?(time: number): number;
  /** Heightmaps the "heightmap" teaching view shows and the API returns, where the model has any. */
  readonly heightmaps?: readonly Heightmap[];
}
