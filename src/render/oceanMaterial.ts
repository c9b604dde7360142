import { Color, ShaderMaterial, Vector3, type CubeTexture, type Texture } from 'three';
import vertexShader from '../../shaders/ocean.vert?raw';
import fragmentShader from '../../shaders/ocean.frag?raw';
import type { SurfaceState } from '../sim/surface';
import { BASE_STEP, CHUNK_QUADS } from '../sim/lodBands';
import { registerShaderChunks } from './shaderChunks';
import { applyHeightmaps, applySurfaceState, createSurfaceUniforms, type SurfaceUniforms } from './surfaceUniforms';

/** Lighter tint where the water faces the viewer, relative to the deep colour. */
const FACING_TINT_LIFT = new Color(0.045, 0.11, 0.12);

export class OceanMaterial extends ShaderMaterial {
  constructor(heightmaps: [Texture, Texture], fresnelTable: Texture, sky: CubeTexture) {
    registerShaderChunks();
    super({
      vertexShader,
      fragmentShader,
      uniforms: {
        ...createSurfaceUniforms(heightmaps),
        uSky: { value: sky },
        uFresnelTable: { value: fresnelTable },
        uFresnelEnabled: { value: true },
        uDeepColor: { value: new Color() },
        uFacingTint: { value: new Color() },
        uSunDirection: { value: new Vector3(0, 1, 0) },
        uSunColor: { value: new Color(1.0, 0.93, 0.8) },
        uHazeDensity: { value: 0.0012 },
        uFlatNormals: { value: false },
        uShowNormals: { value: false },
        uBaseStep: { value: BASE_STEP },
        uChunkQuads: { value: CHUNK_QUADS },
        uLodColors: { value: false },
      },
    });
  }

  setSurface(state: SurfaceState): void {
    applySurfaceState(this.uniforms as SurfaceUniforms, state);
  }

  setHeightmaps(heightmaps: [Texture, Texture]): void {
    applyHeightmaps(this.uniforms as SurfaceUniforms, heightmaps);
  }

  setSky(sky: CubeTexture): void {
    this.uniforms.uSky.value = sky;
  }

  setWaterColor(hex: string): void {
    const deep = (this.uniforms.uDeepColor.value as Color).set(hex);
    (this.uniforms.uFacingTint.value as Color).copy(deep).add(FACING_TINT_LIFT);
  }

  setSunDirection(direction: readonly [number, number, number]): void {
    (this.uniforms.uSunDirection.value as Vector3).fromArray(direction).normalize();
  }

  setTeachingViews(flatNormals: boolean, showNormals: boolean): void {
    this.uniforms.uFlatNormals.value = flatNormals;
    this.uniforms.uShowNormals.value = showNormals;
  }

  setFresnelEnabled(enabled: boolean): void {
    this.uniforms.uFresnelEnabled.value = enabled;
  }

  /** The LOD debugger's view: each chunk tinted by its band. */
  setLodColors(enabled: boolean): void {
    this.uniforms.uLodColors.value = enabled;
  }
}
