import {
  Color,
  DataTexture,
  LinearFilter,
  LinearMipmapNearestFilter,
  LinearSRGBColorSpace,
  RedFormat,
  RepeatWrapping,
  UnsignedByteType,
  Vector3,
  WebGLCubeRenderTarget,
  type CubeTexture,
  type WebGLRenderer,
} from 'three';
import fragmentShader from '../../../shaders/skyDome.frag?raw';
import { CubePainter } from './cubePainter';
import {
  BELOW_HORIZON,
  CLOUD_LIT,
  CLOUD_SHADE,
  DUSK_HORIZON,
  DUSK_ZENITH,
  HORIZON,
  NIGHT_HORIZON,
  NIGHT_ZENITH,
  SUN,
  ZENITH,
  cloudDensityTile,
} from '../../sim/optics/skyPainter';
import { SQUARE_ROOT_SKY } from './skyCubeUniforms';

/**
 * Texels along one side of the baked cloud tile: about 10 per cell of the finest octave
 * (96 cells). At 256 the bilinear lookup flattened the peaks that the cover threshold
 * picks out and the clouds came out visibly thinner than the CPU painter's.
 */
const CLOUD_TILE_SIZE = 1024;

const rgb = (c: readonly [number, number, number]) => new Color(c[0], c[1], c[2]);

/**
 * The default sky, made at run time from the sun: skyDome.frag paints the sky of
 * src/sim/optics/skyPainter.ts for the current sun into a cube render target. It is painted again
 * only when the sun moves (six small passes), never per frame, and the ocean reflects the
 * result exactly as it reflected the shipped cube map.
 */
export class SunSky {
  readonly target: WebGLCubeRenderTarget;
  private readonly painter: CubePainter;
  private readonly clouds: DataTexture;
  private readonly painted = new Vector3(Number.NaN, Number.NaN, Number.NaN);
  /** How many times the cube has been painted: the test that it is not repainted per frame reads it. */
  paintCount = 0;

  constructor(size = 512) {
    // 8 bits a channel holding the colour's square root (shaders/skyCube.glsl says why), with
    // mipmaps: a rough sea reflects the sky blurred (skyCubeColorRough, which blends two levels
    // itself: perf, for SwiftShader only: its trilinear cube filter cost the default view 15 %, docs/light-sun-and-sky.md).
    this.target = new WebGLCubeRenderTarget(size, {
      type: UnsignedByteType,
      generateMipmaps: true,
      minFilter: LinearMipmapNearestFilter,
      magFilter: LinearFilter,
    });
    this.target.texture.colorSpace = LinearSRGBColorSpace;
    this.target.texture.userData[SQUARE_ROOT_SKY] = true;
    const density = cloudDensityTile(CLOUD_TILE_SIZE);
    const bytes = new Uint8Array(density.length);
    // Density lies in [-1, 1]; one byte per texel is finer than the cloud edge's width (0.3).
    for (let k = 0; k < density.length; k++) bytes[k] = Math.round(Math.min(1, Math.max(0, (density[k] + 1) / 2)) * 255);
    this.clouds = new DataTexture(bytes, CLOUD_TILE_SIZE, CLOUD_TILE_SIZE, RedFormat, UnsignedByteType);
    this.clouds.wrapS = this.clouds.wrapT = RepeatWrapping;
    this.clouds.minFilter = this.clouds.magFilter = LinearFilter;
    this.clouds.needsUpdate = true;
    this.painter = new CubePainter(this.target, fragmentShader, {
      uSunDirection: { value: new Vector3(0, 1, 0) },
      uClouds: { value: this.clouds },
      uZenith: { value: rgb(ZENITH) },
      uHorizon: { value: rgb(HORIZON) },
      uBelowHorizon: { value: rgb(BELOW_HORIZON) },
      uSun: { value: rgb(SUN) },
      uCloudLit: { value: rgb(CLOUD_LIT) },
      uCloudShade: { value: rgb(CLOUD_SHADE) },
      uDuskHorizon: { value: rgb(DUSK_HORIZON) },
      uDuskZenith: { value: rgb(DUSK_ZENITH) },
      uNightZenith: { value: rgb(NIGHT_ZENITH) },
      uNightHorizon: { value: rgb(NIGHT_HORIZON) },
    });
  }

  get texture(): CubeTexture {
    return this.target.texture;
  }

  /** Paints the cube for this sun unless it already shows it; returns whether it painted. */
  update(renderer: WebGLRenderer, sun: readonly [number, number, number]): boolean {
    if (this.painted.x === sun[0] && this.painted.y === sun[1] && this.painted.z === sun[2]) return false;
    this.painted.fromArray(sun);
    (this.painter.material.uniforms.uSunDirection.value as Vector3).fromArray(sun);
    this.painter.paint(renderer);
    this.paintCount++;
    return true;
  }

  /**
   * A restored WebGL context gives the cube back empty (three.js re-creates render targets
   * but not what was drawn into them): the next update() paints it again.
   */
  forget(): void {
    this.painted.set(Number.NaN, Number.NaN, Number.NaN);
  }

  dispose(): void {
    this.target.dispose();
    this.painter.dispose();
    this.clouds.dispose();
  }
}
