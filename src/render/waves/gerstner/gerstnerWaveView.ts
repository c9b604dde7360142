import { Vector4, type Camera, type WebGLRenderer } from 'three';
import type { OceanParams } from '../../../sim/params/params';
import type { GerstnerLiveModel } from '../../../sim/waves/gerstner/gerstnerLiveModel';
import { GerstnerWaveUniforms } from './gerstnerWaveUniforms';
import type { WaveModelView } from '../waveModelView';
import { seaSlopeVariance } from '../../../sim/optics/coxMunk';
import { gerstnerFinestVertexStep } from '../../../sim/waves/gerstner/gerstnerVertexStep';

/**
 * Gerstner's trochoids on the GPU: a table of at most 64 waves uploaded once per sea and 64
 * reduced time phases per frame (GerstnerWaveUniforms). No textures, no passes. Its chunk
 * defines WAVE_PIXEL_NORMALS, so ocean.frag evaluates the closed-form normal per pixel.
 */
export class GerstnerWaveView implements WaveModelView {
  readonly name = 'gerstner';
  readonly chunkName = 'oceano_waves_gerstner';
  readonly chunk = GerstnerWaveUniforms.chunk;
  /** The trochoids' wavelengths are drawn from a continuum: the lens height never repeats. */
  readonly lensPeriod = null;
  private readonly table: GerstnerWaveUniforms;
  private readonly viewport = new Vector4();

  constructor(readonly model: GerstnerLiveModel) {
    this.table = new GerstnerWaveUniforms(model.waves);
    this.finestVertexStep = gerstnerFinestVertexStep(model.waves);
  }

  get uniforms(): GerstnerWaveUniforms['uniforms'] {
    return this.table.uniforms;
  }

  /** See WaveModelView: the steep short waves' need (gerstnerFinestVertexStep), for the sea of the last setParams. */
  finestVertexStep = Infinity;

  setParams(params: OceanParams): void {
    if (this.model.setParams(params)) {
      this.table.setWaves(this.model.waves);
      this.finestVertexStep = gerstnerFinestVertexStep(this.model.waves);
    }
    this.table.setSeaSlopeVariance(seaSlopeVariance(params.windSpeed));
  }

  update(time: number): void {
    this.table.update(time);
  }

  setRenderOrigin(x: number, z: number): void {
    this.table.setRenderOrigin(x, z);
  }

  /** The viewport's height spans 2 / P₁₁ of tangent at its centre (P₁₁ = cot(fov / 2)): that over its pixels. */
  setCamera(camera: Camera, renderer: WebGLRenderer): void {
    this.table.setPixelAngle(2 / (camera.projectionMatrix.elements[5] * renderer.getCurrentViewport(this.viewport).w));
  }

  dispose(): void {
    this.table.dispose();
  }
}
