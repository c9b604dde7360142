import { generateRippleHeightmaps, type Heightmap } from '../../noise/perlinNoise';
import type { OceanParams } from '../../params/params';
import { HEIGHTMAP_SIZE, maxDisplacement, surfaceHeight, surfaceNormal, surfaceStateAt, type SurfaceState } from './seedSurface';
import { heightmapSlopeVariance, seedSlopeVariance } from './seedSlopes';
import type { DisplacementBounds, SurfaceSample, WaveModel } from '../waveModel';

/**
 * The parameters the seed's sea reads; everything else in OceanParams leaves it unchanged. Its
 * waves know no wind: the wind only sets the roughness its glint is given (Cox & Munk's σ²
 * less the slopes its normals show, src/render/waves/seed/seedWaveView.ts).
 */
export type SeedWaveParams = Pick<
  OceanParams,
  'seed' | 'swellAmplitude' | 'swellFrequency' | 'rippleStrength' | 'rippleBlendSpeed' | 'windSpeed'
>;

/**
 * The seed report's sea (sines for the swell, two blended Perlin heightmaps for the
 * ripples) as the first WaveModel: the CPU twin of shaders/waves/seed.glsl. It displaces
 * only vertically (dx = dz = 0), so a world point is its own grid point and sample() needs
 * no inversion. The renderer uploads exactly `heightmaps`; the twin samples the same arrays.
 */
export class SeedWaveModel implements WaveModel {
  readonly name = 'seed';
  private seed: number;
  heightmaps: [Heightmap, Heightmap];
  /** Each heightmap's mean-square slope at unit strength, as the fabricated normal takes it. */
  private heightmapSlopes: [number, number];
  private params: SeedWaveParams;
  // The state of the last time asked for: a frame samples many points at one time (boat,
  // underwater switch), and each state costs two square roots and seven reductions.
  private stateTime = Number.NaN;
  private state: SurfaceState | null = null;
  /** See LiveWaveModel: every setParams may change the surface (any of its parameters). */
  surfaceRevision = 0;

  constructor(params: SeedWaveParams) {
    this.params = params;
    this.seed = params.seed;
    this.heightmaps = generateRippleHeightmaps(params.seed, HEIGHTMAP_SIZE);
    this.heightmapSlopes = this.heightmaps.map((map) => heightmapSlopeVariance(map)) as [number, number];
  }

  /** Returns true when the heightmaps were regenerated (the seed changed). */
  setParams(params: SeedWaveParams): boolean {
    this.params = params;
    this.state = null;
    this.surfaceRevision++;
    if (params.seed === this.seed) return false;
    this.seed = params.seed;
    this.heightmaps = generateRippleHeightmaps(params.seed, HEIGHTMAP_SIZE);
    this.heightmapSlopes = this.heightmaps.map((map) => heightmapSlopeVariance(map)) as [number, number];
    return true;
  }

  stateAt(time: number): SurfaceState {
    if (this.state === null || !Object.is(time, this.stateTime)) {
      this.state = surfaceStateAt(this.params, time);
      this.stateTime = time;
    }
    return this.state;
  }

  displacement(x: number, z: number, time: number): [number, number, number] {
    return [0, surfaceHeight(this.stateAt(time), this.heightmaps, x, z), 0];
  }

  /** The height alone, for callers that need no normal (two heightmap samples instead of six). */
  height(x: number, z: number, time: number): number {
    return surfaceHeight(this.stateAt(time), this.heightmaps, x, z);
  }

  sample(x: number, z: number, time: number): SurfaceSample {
    const state = this.stateAt(time);
    return { height: surfaceHeight(state, this.heightmaps, x, z), normal: surfaceNormal(state, this.heightmaps, x, z) };
  }

  /** U₁₀, m/s: the app's wind, which the seed's waves do not follow (see SeedWaveParams). */
  get windSpeed(): number {
    return this.params.windSpeed;
  }

  /** See LiveWaveModel: the swell's and the blended ripples' mean-square slope at `time`. */
  slopeVariance(time: number): number {
    return seedSlopeVariance(this.stateAt(time), this.heightmapSlopes);
  }

  bounds(): DisplacementBounds {
    return { vertical: maxDisplacement(this.params), horizontal: 0 };
  }
}
