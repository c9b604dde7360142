import {
  ClampToEdgeWrapping,
  DataTexture,
  FloatType,
  NearestFilter,
  PlaneGeometry,
  RGBAFormat,
  Vector2,
  type BufferGeometry,
  type Object3D,
} from 'three';
import type { OceanParams } from '../../sim/params/params';
import type { LiveWaveModel } from '../../sim/waves/waveModel';
import type { Submersion } from '../../sim/underwater/snellWindow';
import { seaDepth, type SeaFloor } from '../../sim/coast/bathymetry';
import type { CoastField, CoastSetting } from '../../sim/coast/coastField';
import { CoastSurface } from '../../sim/coast/coastSurface';
import { componentAdvance } from '../../sim/coast/coastSwellSlope';
import { swellComponents, type SwellComponentSpec } from '../../sim/coast/swellSpectrum';
import { BREAKER_INDEX, windSeaHeightOf } from '../../sim/coast/windSeaDamping';
import { sailUntilAground, type SailLimit } from '../../sim/coast/aground';
import { setMaterialDefine } from '../shaders/materialDefines';
import type { OceanMaterial } from '../ocean/oceanMaterial';
import type { SeaBed } from '../underwater/seaBed';
import type { WaveBinding } from '../waves/waveBinding';
import type { WaveModelView } from '../waves/waveModelView';
import { createCoastUniforms } from './coastUniforms';
import { CoastLand } from './coastLand';
import { coastChunk } from './coastChunk';
import { CoastFieldBuilder } from './coastFieldBuilder';

/** The sea bed on a coast: as wide as the flat one, its vertices 10 m apart so that it follows the floor's bends. */
const BED_SIZE = 4000;
const BED_SEGMENTS = 400;
const BED_STEP = BED_SIZE / BED_SEGMENTS;

/** The components shaders/coast.glsl sums: two layers of two. */
const SHADER_COMPONENTS = 4;

/**
 * The field's components as the shader reads them: an N × 2N RGBA float image, two layers
 * stacked in v, texel (i, j) of layer L = (S, A) of component 2L then of component 2L + 1
 * (amplitude 0 for a component the field lacks).
 */
export function packLayers(field: CoastField): Float32Array {
  if (field.components.length > SHADER_COMPONENTS) throw new Error(`CoastScene: the shader sums ${SHADER_COMPONENTS} components at most.`);
  const n = field.resolution;
  const image = new Float32Array(n * n * 2 * 4);
  field.components.forEach((component, m) => {
    const layer = m >> 1;
    const slot = (m & 1) * 2;
    for (let t = 0; t < n * n; t++) {
      const to = (layer * n * n + t) * 4 + slot;
      image[to] = component.texels[t * 2];
      image[to + 1] = component.texels[t * 2 + 1];
    }
  });
  return image;
}

/** The field with each component's phase offset from `components` (the same frequencies, another seed); the texels are shared. */
function withPhaseOffsets(field: CoastField, components: readonly SwellComponentSpec[]): CoastField {
  return { ...field, components: field.components.map((component, m) => ({ ...component, phaseOffset: components[m].phaseOffset })) };
}

/** What the coast needs of the ocean it joins (OceanEngine): its binding, materials, sea bed, model and time. */
export interface CoastHost extends Object3D {
  readonly binding: WaveBinding;
  readonly material: OceanMaterial;
  readonly seaBed: SeaBed;
  readonly waveModelView: WaveModelView;
  readonly time: number;
}

/** The coast's setting from the parameters. */
export function coastSettingOf(params: OceanParams): CoastSetting {
  return {
    bathymetry: params.bathymetry,
    beachSlope: params.beachSlope,
    deepDepth: params.depth,
    swellHeight: params.swellHeight,
    swellPeriod: params.swellPeriod,
    swellDirection: params.swellDirection,
    seed: params.seed,
  };
}

/**
 * Everything the coast adds to an ocean, fetched only when `bathymetry` is not `deep`: its
 * GLSL (shaders/coast.glsl) compiled into the ocean's and the sea bed's programs, the swell's
 * field (built on the CPU, src/sim/coast/) uploaded as a float texture, the land, the sea bed
 * laid on the floor, and the CPU twin of the sea it draws (CoastSurface). Disposed, the ocean
 * is the open sea's again.
 */
export class CoastScene {
  readonly uniforms = createCoastUniforms();
  readonly land: CoastLand;
  private readonly bed = new PlaneGeometry(BED_SIZE, BED_SIZE, BED_SEGMENTS, BED_SEGMENTS).rotateX(-Math.PI / 2);
  private readonly flatBed: BufferGeometry;
  private texture: DataTexture | null = null;
  private field: CoastField | null = null;
  private surface: CoastSurface | null = null;
  private floor: SeaFloor | null = null;
  private windSea = true;
  /** The setting last asked for, and its key without the seed (what a field is built for). */
  private setting: CoastSetting | null = null;
  private requested: string | null = null;
  private arrival: Promise<void> = Promise.resolve();
  private readonly builder = new CoastFieldBuilder();
  private disposed = false;
  /** The compared models' oceans (compare=…) drawn over this coast, each with its own wind-sea limit. */
  private readonly sides = new Map<OceanMaterial, { value: Vector2 }>();

  constructor(private readonly ocean: CoastHost) {
    ocean.binding.late.provide('oceano_coast', coastChunk);
    // The ocean's two programs share one uniforms object.
    Object.assign(ocean.material.uniforms, this.uniforms);
    Object.assign(ocean.seaBed.material.uniforms, this.uniforms);
    this.flatBed = ocean.seaBed.mesh.geometry;
    this.land = new CoastLand(ocean.material.uniforms);
  }

  /** Whether the first field has arrived and the coast is drawn; until then the ocean is the open sea's. */
  get active(): boolean {
    return this.field !== null;
  }

  /** The coast takes over the ocean's programs, its sea bed and the land once it has a field to draw. */
  private activate(): void {
    for (const material of this.materials()) setMaterialDefine(material, 'OCEAN_COAST', true);
    this.ocean.seaBed.mesh.geometry = this.bed;
    this.ocean.add(this.land.mesh);
  }

  private materials() {
    return [this.ocean.material, this.ocean.material.near, this.ocean.seaBed.material];
  }

  /**
   * Builds the field again, in a Worker (coastFieldBuilder.ts), only when the setting changed (a
   * change of the wind sea or the seed alone rebuilds nothing). Settles once the field of this
   * setting is drawn; until then the previous one stays (or, the first time, the open sea).
   */
  setParams(params: OceanParams): Promise<void> {
    const setting = coastSettingOf(params);
    this.setting = setting;
    // The seed moves only the components' phase offsets: a new seed re-phases the field built, not rebuilds it.
    const key = JSON.stringify({ ...setting, seed: undefined });
    this.windSea = params.windSea;
    this.uniforms.uCoastWind.value.x = this.windSea ? 1 : 0;
    if (key !== this.requested) {
      this.requested = key;
      this.arrival = this.builder.build(setting).then((field) => this.adopt(key, field));
      return this.arrival;
    }
    if (this.field && this.floor) {
      this.field = withPhaseOffsets(this.field, swellComponents(setting));
      this.surface?.setCoast(this.field, this.floor, this.windSea);
      this.update(this.ocean.time);
    }
    return this.arrival;
  }

  /** The field of request `key` has arrived: drawn, unless a newer request has replaced it or the coast is gone. */
  private adopt(key: string, built: CoastField | null): void {
    if (this.disposed || key !== this.requested) return;
    if (!built) throw new Error('CoastScene: a deep sea has no coast.');
    const setting = this.setting!;
    // The newest seed's phases, should the seed have changed while the field was being built.
    const field = withPhaseOffsets(built, swellComponents(setting));
    const floor: SeaFloor = { bathymetry: setting.bathymetry, beachSlope: setting.beachSlope, deepDepth: setting.deepDepth };
    if (this.floor?.bathymetry !== floor.bathymetry || this.floor.beachSlope !== floor.beachSlope) this.land.setFloor(floor);
    const first = !this.field;
    this.floor = floor;
    this.field = field;
    this.upload(field);
    this.uniforms.uCoastFloor.value.set(floor.bathymetry === 'island' ? 2 : 1, floor.beachSlope);
    if (first) this.activate();
    this.surface?.setCoast(field, floor, this.windSea);
    // The bed rises through the waves: the caustics' test of which side of the surface a point is on stays in.
    this.ocean.seaBed.setDepth(0, Infinity);
    this.update(this.ocean.time);
  }

  private upload(field: CoastField): void {
    this.texture?.dispose();
    const n = field.resolution;
    const texture = new DataTexture(packLayers(field), n, 2 * n, RGBAFormat, FloatType);
    texture.minFilter = texture.magFilter = NearestFilter;
    texture.wrapS = texture.wrapT = ClampToEdgeWrapping;
    texture.needsUpdate = true;
    this.texture = texture;
    this.uniforms.uCoastField.value = texture;
    this.uniforms.uCoastGrid.value.set(field.originX, field.originZ, field.spacing, n);
  }

  /** The still water's depth at world (x, z), metres, ≤ 0 on land. */
  depth(x: number, z: number): number {
    return this.floor ? seaDepth(this.floor, x, z) : 0;
  }

  /** Where a boat may sail over this floor: it stops where the water is shallower than its draft. */
  readonly sailLimit: SailLimit = (from, to) =>
    this.floor ? sailUntilAground(this.floor, from, to) : { x: to[0], z: to[1], stopped: false };

  /** The CPU twin of the sea drawn over `inner` (the wave model's own twin); null until the first field has arrived. */
  surfaceOver(inner: LiveWaveModel): CoastSurface | null {
    if (!this.field || !this.floor) return null;
    this.surface ??= new CoastSurface(inner, this.field, this.floor, this.windSea);
    this.surface.inner = inner;
    return this.surface;
  }

  /**
   * Each component's phase advance at `time`, ω_m (t mod T_m) − φ_m, reduced here in double
   * precision, and the wind sea's depth limit γ / H for the model drawn (its largest height H
   * from its bounds).
   */
  update(time: number): void {
    if (!this.field) return;
    const advance = [0, 0, 0, 0];
    this.field.components.slice(0, SHADER_COMPONENTS).forEach((component, m) => (advance[m] = componentAdvance(component, time)));
    this.uniforms.uCoastAdvance.value.fromArray(advance);
    this.uniforms.uCoastWind.value.y = windSeaLimit(this.ocean.waveModelView.model);
  }

  /**
   * A compared model's ocean material (compare=…, src/render/compare/) drawn over this same
   * coast: the first call compiles the coast into its programs and shares the field's uniforms;
   * every frame's call sets its own wind-sea limit, from its own model's waves.
   */
  dressSide(material: OceanMaterial, model: LiveWaveModel): void {
    if (!this.field) return;
    let wind = this.sides.get(material);
    if (!wind) {
      wind = { value: new Vector2() };
      Object.assign(material.uniforms, this.uniforms, { uCoastWind: wind });
      for (const program of [material, material.near]) setMaterialDefine(program, 'OCEAN_COAST', true);
      this.sides.set(material, wind);
    }
    wind.value.set(this.windSea ? 1 : 0, windSeaLimit(model));
  }

  /**
   * The land above the water; from under it the sea bed, on the same floor, takes over. The bed,
   * which follows the eye, moves in whole cells, so its vertices stay on the same floor points.
   */
  shade(submersion: Submersion): void {
    this.land.mesh.visible = submersion === 'above';
    const position = this.ocean.seaBed.mesh.position;
    position.x = Math.round(position.x / BED_STEP) * BED_STEP;
    position.z = Math.round(position.z / BED_STEP) * BED_STEP;
  }

  dispose(): void {
    this.disposed = true;
    this.builder.dispose();
    for (const material of [...this.materials(), ...[...this.sides.keys()].flatMap((side) => [side, side.near])]) {
      setMaterialDefine(material, 'OCEAN_COAST', false);
    }
    this.sides.clear();
    this.ocean.seaBed.mesh.geometry = this.flatBed;
    this.bed.dispose();
    this.land.mesh.removeFromParent();
    this.land.dispose();
    this.texture?.dispose();
  }
}

/** γ / H: the breaker index over the largest height of `model`'s waves, the wind sea's depth limit in shaders/coast.glsl. */
function windSeaLimit(model: LiveWaveModel): number {
  const height = windSeaHeightOf(model.bounds().vertical);
  return height > 0 ? BREAKER_INDEX / height : 1e6;
}
