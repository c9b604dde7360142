import { Color, Mesh, PlaneGeometry, ShaderMaterial, Vector3, type DataTexture, type IUniform } from 'three';
import vertexShader from '../../../shaders/seabed.vert?raw';
import fragmentShader from '../../../shaders/seabed.frag?raw';
import { markOceanoMaterial } from './sceneEncoding';
import { setMaterialDefine } from '../shaders/materialDefines';
import { generateHeightmap, defaultNoiseSettings } from '../../sim/noise/perlinNoise';
import { HEIGHTMAP_SIZE, RIPPLE_TILE_SIZE } from '../../sim/waves/seed/seedSurface';
import { heightmapTexture } from '../optics/dataTextures';
import type { WaveBinding } from '../waves/waveBinding';
import type { WaterVolumeUniforms } from './waterVolumeUniforms';
import type { CausticsUniforms } from './causticsUniforms';

/** Side of the flat bed, metres: far past where the water fog has hidden everything. */
const BED_SIZE = 4000;
const SAND = new Color(0.55, 0.47, 0.33);

/**
 * A flat sand bed at a configurable depth under the mean sea level, lit through the
 * waves with caustics. It follows the camera in x and z; its pattern is in world space.
 */
export class SeaBed {
  readonly mesh: Mesh;
  readonly material: ShaderMaterial;
  private mottleSeed = Number.NaN;
  private mottle: DataTexture | null = null;

  constructor(waves: WaveBinding, shared: WaterVolumeUniforms & CausticsUniforms & Record<'uRefractedSun' | 'uSunColor', IUniform>) {
    this.material = waves.attach(
      markOceanoMaterial(
        new ShaderMaterial({
          vertexShader,
          fragmentShader,
          uniforms: {
            ...shared,
            uSandColor: { value: SAND.clone() },
            uSunTransmission: { value: 1 },
            uSandMottle: { value: null },
            uSandMottleTile: { value: RIPPLE_TILE_SIZE },
            uSandMottleSize: { value: HEIGHTMAP_SIZE },
          },
        }),
      ),
    );
    const geometry = new PlaneGeometry(BED_SIZE, BED_SIZE);
    geometry.rotateX(-Math.PI / 2);
    this.mesh = new Mesh(geometry, this.material);
    this.mesh.frustumCulled = false;
    this.mesh.visible = false;
  }

  /**
   * The sand's mottling is the noise seed's second ripple heightmap (the seed model's own
   * uHeightmap1, whatever wave model runs), at a scale of its own.
   */
  setNoiseSeed(seed: number): void {
    if (seed === this.mottleSeed) return;
    this.mottleSeed = seed;
    this.mottle?.dispose();
    this.mottle = heightmapTexture(generateHeightmap(HEIGHTMAP_SIZE, { ...defaultNoiseSettings, seed: seed * 2 + 1 }));
    this.material.uniforms.uSandMottle.value = this.mottle;
  }

  /**
   * The bed's depth under the mean sea level, and the waves' vertical reach (the model's
   * bound): a bed deeper than every trough is always under the water, so caustics.glsl's
   * test of whether a point is above the surface (one full evaluation of the displacement per
   * pixel) is compiled out (CAUSTICS_BELOW_WAVES).
   * perf: on a GPU the test would be a branch most pixels skip; the define matters for a software
   * rasterizer, which runs both sides of a branch (docs/performance.md, "Software rasterizer").
   */
  setDepth(depth: number, waveReach: number): void {
    this.mesh.position.y = -depth;
    setMaterialDefine(this.material, 'CAUSTICS_BELOW_WAVES', depth > waveReach);
  }

  /** Whether the bed's program leaves out the caustics' above-the-surface test (for tests). */
  get belowWaves(): boolean {
    return 'CAUSTICS_BELOW_WAVES' in this.material.defines;
  }

  /** Share of the sunlight a flat sea lets through (1 − Fresnel reflectance at the sun's angle). */
  setSunTransmission(transmission: number): void {
    this.material.uniforms.uSunTransmission.value = transmission;
  }

  follow(eye: Vector3): void {
    this.mesh.position.x = eye.x;
    this.mesh.position.z = eye.z;
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    this.material.dispose();
    this.mottle?.dispose();
  }
}
