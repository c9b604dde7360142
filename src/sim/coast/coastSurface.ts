import { undoHorizontalDisplacement, type DisplacementBounds, type LiveWaveModel, type SurfaceSample } from '../waves/waveModel';
import type { OceanParams } from '../params/params';
import { seaDepth, type SeaFloor } from './bathymetry';
import type { CoastField } from './coastField';
import { coastSwellWithSlope } from './coastSwellSlope';
import { windSeaFactor, windSeaHeightOf } from './windSeaDamping';

/**
 * The sea at the coast, the CPU twin of ocean.vert with OCEAN_COAST: the swell of the coast's
 * field plus the wave model's own waves (the wind sea), calmed where the water is shallow.
 * A grid point p of the wind sea moves by f D(p), its whole displacement (sideways too) scaled
 * by f = min(1, γ h(p) / H_wind), and the swell is added at the point it lands on:
 *   η(p + f D_xz(p), t) = f D_y(p, t) + s Re Σ A_m e^{i(S_m − ω_m t + φ_m)}
 * (s: the swell's envelope limit, coastSwellSlope.ts), the normal tilted likewise. The boat, the underwater switch and the API read it as they
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
    if (!this.windSea) return [0, coastSwellWithSlope(this.field, x, z, time)[0], 0];
    const f = this.windFactor(x, z);
    const d = this.inner.displacement(x, z, time);
    const [swell] = coastSwellWithSlope(this.field, x + f * d[0], z + f * d[2], time);
    return [f * d[0], f * d[1] + swell, f * d[2]];
  }

  sample(x: number, z: number, time: number): SurfaceSample {
    const wind = this.windAt(x, z, time);
    const [swell, swellX, swellZ] = coastSwellWithSlope(this.field, x, z, time);
    // The swell's slope, and the wind sea's (from its normal, −n.xz / n.y) scaled by the factor.
    const slopeX = swellX - (wind.factor * wind.normal[0]) / Math.max(wind.normal[1], 1e-4);
    const slopeZ = swellZ - (wind.factor * wind.normal[2]) / Math.max(wind.normal[1], 1e-4);
    const length = Math.hypot(slopeX, 1, slopeZ);
    return {
      height: wind.factor * wind.height + swell,
      normal: [-slopeX / length, 1 / length, -slopeZ / length],
    };
  }

  height(x: number, z: number, time: number): number {
    const wind = this.windAt(x, z, time);
    return wind.factor * wind.height + coastSwellWithSlope(this.field, x, z, time)[0];
  }

  /**
   * The wind sea above the world point (x, z): the height and normal of its grid point p, the
   * one whose calmed displacement lands there (p + f(p) D_xz(p) = (x, z)), and that point's f.
   * Where every grid point that could land there has f = 1 (deep enough within the wind sea's
   * sideways reach), that is the wave model's own answer at (x, z).
   */
  private windAt(x: number, z: number, time: number): { height: number; normal: [number, number, number]; factor: number } {
    if (!this.windSea) return { height: 0, normal: [0, 1, 0], factor: 0 };
    const { vertical, horizontal } = this.inner.bounds();
    const depthAcrossReach = seaDepth(this.floor, x, z) - this.floor.beachSlope * horizontal;
    if (windSeaFactor(depthAcrossReach, windSeaHeightOf(vertical)) >= 1) return { ...this.inner.sample(x, z, time), factor: 1 };
    const calmed = (px: number, pz: number): [number, number, number] => {
      const f = this.windFactor(px, pz);
      const d = this.inner.displacement(px, pz, time);
      return [f * d[0], f * d[1], f * d[2]];
    };
    const p = undoHorizontalDisplacement(calmed, x, z);
    const d = this.inner.displacement(p.x, p.z, time);
    // The model's normal at p, read where the model alone puts p.
    const { normal } = this.inner.sample(p.x + d[0], p.z + d[2], time);
    return { height: d[1], normal, factor: this.windFactor(p.x, p.z) };
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
