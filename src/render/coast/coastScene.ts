import { ClampToEdgeWrapping, DataTexture, FloatType, NearestFilter, RGBAFormat, type IUniform, type Object3D } from 'three';
import type { OceanParams } from '../../sim/params/params';
import type { LiveWaveModel } from '../../sim/waves/waveModel';
import type { SeaFloor } from '../../sim/coast/bathymetry';
import type { CoastField, CoastSetting } from '../../sim/coast/coastField';
import { buildCoastField } from '../../sim/coast/buildCoastField';
import { CoastSurface } from '../../sim/coast/coastSurface';
import { BREAKER_INDEX, windSeaHeightOf } from '../../sim/coast/windSeaDamping';
import type { CoastUniforms } from './coastUniforms';
import { CoastLand } from './coastLand';

export { coastChunk } from './coastChunk';

/** The coast's setting and whether the wind sea is drawn over its swell, from the parameters. */
export function coastSettingOf(params: OceanParams): CoastSetting {
  return {
    bathymetry: params.bathymetry,
    beachSlope: params.beachSlope,
    deepDepth: params.depth,
    swellHeight: params.swellHeight,
    swellPeriod: params.swellPeriod,
    swellDirection: params.swellDirection,
  };
}

/**
 * Everything the coast adds to an ocean, fetched only when `bathymetry` is not `deep`: the
 * swell's field (built on the CPU, src/sim/coast/) uploaded as a float texture for
 * shaders/coast.glsl, the land, and the CPU twin of the sea it draws (CoastSurface).
 */
export class CoastScene {
  readonly land: CoastLand;
  private texture: DataTexture | null = null;
  private field: CoastField | null = null;
  private surface: CoastSurface | null = null;
  private floor: SeaFloor | null = null;
  private windSea = true;
  private built: string | null = null;

  constructor(
    private readonly uniforms: CoastUniforms,
    look: Record<string, IUniform>,
    parent: Object3D,
  ) {
    this.land = new CoastLand(look);
    parent.add(this.land.mesh);
  }

  /** Builds the field again only when the setting changed (a change of the wind sea alone rebuilds nothing). */
  setParams(params: OceanParams): void {
    const setting = coastSettingOf(params);
    const key = JSON.stringify(setting);
    this.windSea = params.windSea;
    if (key !== this.built) {
      this.built = key;
      const floor: SeaFloor = { bathymetry: setting.bathymetry, beachSlope: setting.beachSlope, deepDepth: setting.deepDepth };
      if (this.floor?.bathymetry !== floor.bathymetry || this.floor.beachSlope !== floor.beachSlope) this.land.setFloor(floor);
      this.floor = floor;
      this.field = buildCoastField(setting);
      this.upload(this.field);
      this.uniforms.uCoastFloor.value.set(floor.bathymetry === 'island' ? 2 : 1, floor.beachSlope);
    }
    this.uniforms.uCoastWind.value.x = this.windSea ? 1 : 0;
    if (this.surface && this.field && this.floor) this.surface.setCoast(this.field, this.floor, this.windSea);
  }

  private upload(field: CoastField): void {
    this.texture?.dispose();
    const texture = new DataTexture(field.texels, field.resolution, field.resolution, RGBAFormat, FloatType);
    texture.minFilter = texture.magFilter = NearestFilter;
    texture.wrapS = texture.wrapT = ClampToEdgeWrapping;
    texture.needsUpdate = true;
    this.texture = texture;
    this.uniforms.uCoastField.value = texture;
    this.uniforms.uCoastGrid.value.set(field.originX, field.originZ, field.spacing, field.resolution);
  }

  /** The CPU twin of the sea drawn over `inner` (the wave model's own twin). */
  surfaceOver(inner: LiveWaveModel): CoastSurface {
    if (!this.field || !this.floor) throw new Error('CoastScene.surfaceOver: setParams first.');
    this.surface ??= new CoastSurface(inner, this.field, this.floor, this.windSea);
    this.surface.inner = inner;
    return this.surface;
  }

  /**
   * The swell's phase advance at `time`, ω (t mod T), reduced here in double precision, and the
   * wind sea's depth limit γ / H for the model drawn (its largest height H from its bounds).
   */
  update(time: number, inner: LiveWaveModel): void {
    if (!this.field) return;
    const period = (2 * Math.PI) / this.field.angularFrequency;
    this.uniforms.uCoastAdvance.value = this.field.angularFrequency * (time - period * Math.floor(time / period));
    const height = windSeaHeightOf(inner.bounds().vertical);
    this.uniforms.uCoastWind.value.y = height > 0 ? BREAKER_INDEX / height : 1e6;
  }

  dispose(): void {
    this.land.mesh.removeFromParent();
    this.land.dispose();
    this.texture?.dispose();
  }
}
