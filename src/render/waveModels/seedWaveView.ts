import type { DataTexture } from 'three';
import seedChunk from '../../../shaders/waves/seed.glsl?raw';
import type { OceanParams } from '../../sim/params';
import type { SeedWaveModel } from '../../sim/seedWaveModel';
import { RIPPLE_TILE_SIZE } from '../../sim/surface';
import { heightmapTexture } from '../dataTextures';
import { registerChunk, registerShaderChunks } from '../shaderChunks';
import type { WaveModelView } from './waveModelView';
import { applyHeightmaps, applySurfaceState, createSurfaceUniforms, type SurfaceUniforms } from './seedUniforms';

/** The seed's sines and Perlin ripples on the GPU: two heightmap textures and the per-frame phases. */
export class SeedWaveView implements WaveModelView {
  readonly name = 'seed';
  readonly chunkName = 'oceano_waves_seed';
  /** The lens is the ripples alone, two heightmaps tiled on the same 96 m square. */
  readonly lensPeriod = RIPPLE_TILE_SIZE;
  readonly uniforms: SurfaceUniforms;
  heightmapTextures: [DataTexture, DataTexture];

  constructor(readonly model: SeedWaveModel) {
    registerChunk(this.chunkName, seedChunk);
    registerShaderChunks();
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
    applySurfaceState(this.uniforms, this.model.stateAt(time));
  }

  dispose(): void {
    for (const texture of this.heightmapTextures) texture.dispose();
  }
}
