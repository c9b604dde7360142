import { Vector4, type IUniform } from 'three';
import gerstnerChunk from '../../../../shaders/waves/gerstner.glsl?raw';
import { gerstnerTimePhases, type GerstnerWave } from '../../../sim/waves/gerstner/gerstnerWaves';
import { gerstnerOriginPhases } from '../../../sim/waves/originPhases';
import { gerstnerWavenumber, trochoidSlopeVariance } from '../../../sim/waves/gerstner/gerstnerSlopes';

/** Must equal GERSTNER_MAX_WAVES in shaders/waves/gerstner.glsl (params.gerstnerCount's maximum). */
export const GERSTNER_MAX_WAVES = 64;

export type GerstnerUniforms = Record<
  'uGerstnerCount' | 'uGerstnerWaves' | 'uGerstnerPhases' | 'uGerstnerNearPhases' | 'uGerstnerSlopes' | 'uSeaSlopeVariance' | 'uPixelAngle',
  IUniform
>;

/** Four phases per vec4, zeros past the last wave. */
function pack(phases: ArrayLike<number>, packed: Vector4[]): void {
  const at = (i: number) => (i < phases.length ? phases[i] : 0);
  for (let j = 0; j < packed.length; j++) packed[j].set(at(4 * j), at(4 * j + 1), at(4 * j + 2), at(4 * j + 3));
}

/**
 * The render side of the Gerstner model: its GLSL chunk (shaders/waves/gerstner.glsl, which
 * defines waveDisplacement and waveNormal per the wave-model seam), the uniforms that chunk
 * reads, and the per-frame update. The wave table is uploaded once per sea, longest wave
 * first (the chunk sums the long waves per vertex and stops its per-pixel sum at the first
 * wave a pixel cannot resolve), with each wave's mean-square slope; each frame only the 64
 * reduced time phases change, computed in double precision on the CPU by the same function
 * the CPU twin uses, so GPU and CPU see one surface.
 */
export class GerstnerWaveUniforms {
  static readonly chunk: string = gerstnerChunk;

  readonly uniforms: GerstnerUniforms;
  private waves: readonly GerstnerWave[] = [];
  private timePhases: ArrayLike<number> = [];
  private origin: [number, number] = [0, 0];

  constructor(waves: readonly GerstnerWave[]) {
    this.uniforms = {
      uGerstnerCount: { value: 0 },
      uGerstnerWaves: { value: Array.from({ length: GERSTNER_MAX_WAVES }, () => new Vector4()) },
      uGerstnerPhases: { value: Array.from({ length: GERSTNER_MAX_WAVES / 4 }, () => new Vector4()) },
      uGerstnerNearPhases: { value: Array.from({ length: GERSTNER_MAX_WAVES / 4 }, () => new Vector4()) },
      uGerstnerSlopes: { value: Array.from({ length: GERSTNER_MAX_WAVES / 4 }, () => new Vector4()) },
      uSeaSlopeVariance: { value: 0 },
      uPixelAngle: { value: 1e-3 },
    };
    this.setWaves(waves);
  }

  /** A new sea (seed, wind, count or steepness changed). Waves beyond the count are zeroed. */
  setWaves(waves: readonly GerstnerWave[]): void {
    if (waves.length > GERSTNER_MAX_WAVES) throw new Error(`At most ${GERSTNER_MAX_WAVES} Gerstner waves, got ${waves.length}.`);
    // A sea drawn from a spectrum comes longest first already (drawGerstnerWaves); the sort keeps any other table right.
    waves = [...waves].sort((a, b) => gerstnerWavenumber(a) - gerstnerWavenumber(b));
    this.waves = waves;
    pack(
      waves.map((w) => trochoidSlopeVariance(w.amplitude, gerstnerWavenumber(w), w.horizontal)),
      this.uniforms.uGerstnerSlopes.value as Vector4[],
    );
    // Until the next update the phases are the new sea's at t = 0 (never drawn so: update comes first).
    this.timePhases = gerstnerTimePhases(waves, 0);
    this.uniforms.uGerstnerCount.value = waves.length;
    const table = this.uniforms.uGerstnerWaves.value as Vector4[];
    for (let i = 0; i < GERSTNER_MAX_WAVES; i++) {
      const w = waves[i];
      if (w) table[i].set(w.cx, w.cz, w.amplitude, w.horizontal);
      else table[i].set(0, 0, 0, 0);
    }
  }

  /** Uploads τᵢ(time) = fract(φᵢ − ωᵢ t / 2π), reduced in double precision, and the same at the render origin. */
  update(time: number): void {
    this.timePhases = gerstnerTimePhases(this.waves, time);
    pack(this.timePhases, this.uniforms.uGerstnerPhases.value as Vector4[]);
    this.packNearPhases();
  }

  /** The render origin the pixels' relative grid points are measured from (OceanMaterial.onBeforeRender). */
  setRenderOrigin(x: number, z: number): void {
    if (x === this.origin[0] && z === this.origin[1]) return;
    this.origin = [x, z];
    this.packNearPhases();
  }

  private packNearPhases(): void {
    const near = gerstnerOriginPhases(this.waves, this.timePhases, this.origin[0], this.origin[1]);
    pack(near, this.uniforms.uGerstnerNearPhases.value as Vector4[]);
  }

  /** Cox & Munk's σ² for the wind (src/sim/optics/coxMunk.ts), of which the normals show the trochoids' own. */
  setSeaSlopeVariance(variance: number): void {
    this.uniforms.uSeaSlopeVariance.value = variance;
  }

  /** Radians of view per pixel of the camera about to draw: the vertices' estimate of a pixel's footprint. */
  setPixelAngle(radians: number): void {
    this.uniforms.uPixelAngle.value = radians;
  }

  /** Nothing GPU-side is owned (no textures or targets); kept for the seam's interface. */
  dispose(): void {
    this.waves = [];
    this.uniforms.uGerstnerCount.value = 0;
  }
}
