import type { CubeTexture, IUniform, Texture, WebGLRenderer } from 'three';
import type { OceanParams } from '../../sim/params/params';
import type { DisplacementBounds } from '../../sim/waves/waveModel';
import type { WavesChoice } from '../../sim/waves/waveModel';
import { OceanMaterial } from '../ocean/oceanMaterial';
import { OceanChunks } from '../lod/oceanChunks';
import { WaveBinding } from '../waves/waveBinding';
import { createWaveModelView } from '../waves/waveViewRegistry';
import type { WaveModelView } from '../waves/waveModelView';
import type { WaterVolumeUniforms } from '../underwater/waterVolumeUniforms';
import type { WakeUniforms } from '../wake/wakeUniforms';
import type { FoamUniforms } from '../foam/foamUniforms';
import type { LateChunks } from '../shaders/lateChunks';

/** What every ocean material of one view shares: Fresnel tables, sky, water volume, sun colour. */
export interface OceanMaterialInputs {
  fresnelTables: { fromAbove: Texture; fromBelow: Texture };
  sky: CubeTexture;
  /** Uniforms every ocean material shares: the water volume, the boat's wake (each material compiles it in while it has a track), the sun's colour. */
  shared: WaterVolumeUniforms & WakeUniforms & FoamUniforms & Record<'uSunColor', IUniform>;
  /** The shader chunks that arrive later, shared with the view's own binding. */
  late: LateChunks;
}

/**
 * One extra model of the side-by-side view (compare=a,b[,c]), beside the view's own first
 * model: its own live model (CPU twin), its own GPU half, its own ocean material bound to it
 * through its own WaveBinding (so `#include <oceano_waves>` resolves to its chunk) and its
 * own chunk meshes, culled with its own displacement bounds. The view shows its group only
 * while it draws this model's strip, so each strip is drawn exactly as that model alone.
 */
export class CompareSide {
  readonly view: WaveModelView;
  readonly material: OceanMaterial;
  readonly chunks: OceanChunks;
  private readonly binding: WaveBinding;

  constructor(name: WavesChoice, params: OceanParams, renderer: WebGLRenderer, inputs: OceanMaterialInputs) {
    this.view = createWaveModelView({ ...params, waves: name }, renderer);
    this.binding = new WaveBinding(this.view, inputs.late);
    this.material = new OceanMaterial(this.binding, inputs.fresnelTables, inputs.sky, inputs.shared);
    this.chunks = new OceanChunks(this.material);
    this.chunks.group.visible = false;
  }

  get name(): WavesChoice {
    return this.view.name;
  }

  bounds(): DisplacementBounds {
    return this.view.model.bounds();
  }

  dispose(): void {
    this.chunks.group.removeFromParent();
    this.chunks.dispose();
    this.material.detachFrom(this.binding);
    this.material.dispose();
    this.binding.dispose();
    this.view.dispose();
  }
}
