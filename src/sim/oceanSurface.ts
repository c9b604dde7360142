import { generateRippleHeightmaps, type Heightmap } from './perlinNoise';
import type { OceanParams } from './params';
import { HEIGHTMAP_SIZE, surfaceHeight, surfaceNormal, surfaceStateAt, type SurfaceState } from './surface';

export interface SurfaceSample {
  height: number;
  normal: [number, number, number];
}

/**
 * The ocean surface as data: the current parameters and the two ripple heightmaps made
 * from their seed. The renderer uploads exactly these arrays; the CPU twin samples them.
 */
export class OceanSurface {
  private seed: number;
  heightmaps: [Heightmap, Heightmap];

  constructor(private params: OceanParams) {
    this.seed = params.seed;
    this.heightmaps = generateRippleHeightmaps(params.seed, HEIGHTMAP_SIZE);
  }

  /** Returns true when the heightmaps were regenerated (the seed changed). */
  setParams(params: OceanParams): boolean {
    this.params = params;
    if (params.seed === this.seed) return false;
    this.seed = params.seed;
    this.heightmaps = generateRippleHeightmaps(params.seed, HEIGHTMAP_SIZE);
    return true;
  }

  stateAt(time: number): SurfaceState {
    return surfaceStateAt(this.params, time);
  }

  sample(x: number, z: number, time: number): SurfaceSample {
    const state = this.stateAt(time);
    return { height: surfaceHeight(state, this.heightmaps, x, z), normal: surfaceNormal(state, this.heightmaps, x, z) };
  }
}
