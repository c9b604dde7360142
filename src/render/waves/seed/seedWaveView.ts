import type { DataTexture } from 'three';
import seedChunk from '../../../../shaders/waves/seed.glsl?raw';
import type { OceanParams } from '../../../sim/params/params';
import type { SeedWaveModel } from '../../../sim/waves/seed/seedWaveModel';
import { RIPPLE_TILE_SIZE, type SurfaceState } from '../../../sim/waves/seed/seedSurface';
import { heightmapTexture } from '../../optics/dataTextures';
import { seaSlopeVariance } from '../../../sim/optics/coxMunk';
import { SUN_DISC_SLOPE_VARIANCE } from '../../../sim/optics/sunDisc';
import type { WaveModelView } from '../waveModelView';
import { applyHeightmaps, applySurfaceState, createSurfaceUniforms, type SurfaceUniforms } from './seedUniforms';

/** The seed's sines and Perlin ripples on the GPU: two heightmap textures and the per-frame phases. */
export class SeedWaveView implements WaveModelView {
  readonly name = 'seed';
  readonly chunkName = 'oceano_waves_seed';
  readonly chunk = seedChunk;
  /** The lens is the ripples alone, two heightmaps tiled on the same 96 m square. */
  readonly lensPeriod = RIPPLE_TILE_SIZE;
  readonly uniforms: SurfaceUniforms;
  heightmapTextures: [DataTexture, DataTexture];
  /** The surface state the uniforms hold (SeedWaveModel.stateAt's object); null before the first update. */
  private applied: SurfaceState | null = null;

  constructor(readonly model: SeedWaveModel) {
    this.heightmapTextures = model.heightmaps.map(heightmapTexture) as [DataTexture, DataTexture];
    this.uniforms = createSurfaceUniforms(this.heightmapTextures);
  }

  setParams(params: OceanParams): void {
    if (!this.model.setParams(params)) return;
    for (const texture of this.heightmapTextures) texture.dispose();
    this.heightmapTextures = this.model.heightmaps.map(heightmapTexture) as [DataTexture, DataTexture];
    applyHeightmaps(this.uniforms, this.heightmapTextures);
  }

  update(time: number): void {
    // The model keeps one state per time and parameters (a new object when either changes),
    // and only this writes these uniforms: the state already applied is there already.
    const state = this.model.stateAt(time);
    if (state === this.applied) return;
    this.applied = state;
    applySurfaceState(this.uniforms, state);
    // Cox & Munk's σ² for the app's wind less the slopes the normals show, never smoother than
    // the sun's disc allows (as src/sim/optics/resolvedSlopes.ts unresolvedSlopeVariance).
    this.uniforms.uSlopeRoughness.value = Math.max(
      SUN_DISC_SLOPE_VARIANCE,
      seaSlopeVariance(this.model.windSpeed) - this.model.slopeVariance(time),
    );
  }

  uniformRoughness(): number {
    return this.uniforms.uSlopeRoughness.value as number;
  }

  dispose(): void {
    for (const texture of this.heightmapTextures) texture.dispose();
  }
}
