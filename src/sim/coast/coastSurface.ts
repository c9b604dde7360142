import type { DisplacementBounds, LiveWaveModel, SurfaceSample } from '../waves/waveModel';
import type { OceanParams } from '../params/params';
import { seaDepth, type SeaFloor } from './bathymetry';
import type { CoastField } from './coastField';
import { coastSwellWithSlope } from './coastSwellSlope';
import { windSeaFactor, windSeaHeightOf } from './windSeaDamping';

/**
 * The sea at the coast, the CPU twin of ocean.vert with OCEAN_COAST: the swell of the coast's
 * field plus the wave model's own waves (the wind sea), calmed where the water is shallow,
 * both taken at the world point as the vertex shader takes them at the displaced vertex
 *   η(x, z, t) = f(h) η_wind(x, z, t) + s Re Σ A_m e^{i(S_m − ω_m t + φ_m)},  f = min(1, γ h / H_wind)
 * (s: the swell's envelope limit, coastSwellSlope.ts)
 * and the normal tilted likewise. The boat, the underwater switch and the API read it as they
 * read any wave model. With the wind sea off only the swell is left.
 */
export class CoastSurface implements LiveWaveModel {
  private revision = 0;
  private swellBound = 0;

  constructor(
    public inner: LiveWaveModel,
    private field: CoastField,
    private floor: SeaFloor,
    private windSea: boolean,
  ) {
    this.swellBound = swellBound(field);
  }

  /** A new field, floor or wind-sea switch: every answer may change. */
  setCoast(field: CoastField, floor: SeaFloor, windSea: boolean): void {
    this.field = field;
    this.floor = floor;
    this.windSea = windSea;
    this.swellBound = swellBound(field);
    this.revision++;
  }

  get name(): LiveWaveModel['name'] {
    return this.inner.name;
  }

  get surfaceRevision(): number {
    return this.inner.surfaceRevision + this.revision * 1e9;
  }

  get heightmaps(): LiveWaveModel['heightmaps'] {
    return this.inner.heightmaps;
  }

  setParams(params: OceanParams): boolean {
    return this.inner.setParams(params);
  }

  /** The wind sea's share at world (x, z): min(1, γ h / H), 0 with it off. */
  windFactor(x: number, z: number): number {
    if (!this.windSea) return 0;
    return windSeaFactor(seaDepth(this.floor, x, z), windSeaHeightOf(this.inner.bounds().vertical));
  }

  displacement(x: number, z: number, time: number): [number, number, number] {
    const d: [number, number, number] = this.windSea ? this.inner.displacement(x, z, time) : [0, 0, 0];
    const wx = x + d[0];
    const wz = z + d[2];
    return [d[0], this.windFactor(wx, wz) * d[1] + coastSwellWithSlope(this.field, wx, wz, time)[0], d[2]];
  }

  sample(x: number, z: number, time: number): SurfaceSample {
    const wind = this.windSea ? this.inner.sample(x, z, time) : { height: 0, normal: [0, 1, 0] as [number, number, number] };
    const factor = this.windFactor(x, z);
    const [swell, swellX, swellZ] = coastSwellWithSlope(this.field, x, z, time);
    // The swell's slope, and the wind sea's (from its normal, −n.xz / n.y) scaled by the factor.
    const slopeX = swellX - (factor * wind.normal[0]) / Math.max(wind.normal[1], 1e-4);
    const slopeZ = swellZ - (factor * wind.normal[2]) / Math.max(wind.normal[1], 1e-4);
    const length = Math.hypot(slopeX, 1, slopeZ);
    return {
      height: factor * wind.height + swell,
      normal: [-slopeX / length, 1 / length, -slopeZ / length],
    };
  }

  height(x: number, z: number, time: number): number {
    const wind = this.windSea ? this.inner.height(x, z, time) : 0;
    return this.windFactor(x, z) * wind + coastSwellWithSlope(this.field, x, z, time)[0];
  }

  /** The model's bounds grown by the swell's largest height (swellBound), so culling stays safe. */
  bounds(): DisplacementBounds {
    const inner = this.inner.bounds();
    return { vertical: (this.windSea ? inner.vertical : 0) + this.swellBound, horizontal: this.windSea ? inner.horizontal : 0 };
  }

  slopeVariance(time: number): number {
    return this.windSea ? this.inner.slopeVariance(time) : 0;
  }

  takeMainThreadMs(): number {
    return this.inner.takeMainThreadMs?.() ?? 0;
  }
}

/**
 * The largest |η| the swell can reach anywhere, metres: |η| ≤ min(|Z|, γ h / 2) and |Z| ≤ Σ A_m,
 * so per cell of the grid the least of Σ A_m and γ h / 2 at their corners' largest values (A is
 * bilinear between the corners; h is largest at a corner, a plane or a cone's clamped slope),
 * and the largest over the cells. Beyond the grid the field and the depth are the edge's.
 */
export function swellBound(field: CoastField): number {
  const n = field.resolution;
  const sum = new Float64Array(n * n);
  for (const component of field.components) for (let t = 0; t < n * n; t++) sum[t] += Math.abs(component.texels[t * 2 + 1]);
  const depth = new Float64Array(n * n);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++)
      depth[j * n + i] = seaDepth(field.floor, field.originX + i * field.spacing, field.originZ + j * field.spacing);
  let largest = 0;
  for (let j = 0; j < n - 1; j++) {
    for (let i = 0; i < n - 1; i++) {
      const t = j * n + i;
      const amplitude = Math.max(sum[t], sum[t + 1], sum[t + n], sum[t + n + 1]);
      const deepest = Math.max(depth[t], depth[t + 1], depth[t + n], depth[t + n + 1]);
      largest = Math.max(largest, Math.min(amplitude, (field.breakerIndex * Math.max(0, deepest)) / 2));
    }
  }
  return largest;
}
