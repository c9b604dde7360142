import {
  LinearFilter,
  LinearMipmapLinearFilter,
  LinearMipmapNearestFilter,
  LinearSRGBColorSpace,
  NearestMipmapLinearFilter,
  NearestMipmapNearestFilter,
  type ShaderMaterial,
  UnsignedByteType,
  WebGLCubeRenderTarget,
  type CubeTexture,
  type Vector3,
  type WebGLRenderer,
} from 'three';
import fragmentShader from '../../../shaders/prefilteredSky.frag?raw';
import { CubePainter } from './cubePainter';
import { setMaterialDefine } from '../shaders/materialDefines';
import { prefilteredFaceSize, skyBlurLevel, slopeVarianceAtLevel } from '../../sim/optics/skyBlurLevel';
import { createSkyCubeUniforms, setSkyCube, SQUARE_ROOT_SKY, type SkyCubeUniforms } from './skyCubeUniforms';

/** The blur's mip level is rounded to a 64th of a level: finer than any picture shows (docs/light-cost.md). */
const LEVEL_STEPS = 64;

const MIPMAP_FILTERS: readonly number[] = [
  NearestMipmapNearestFilter,
  NearestMipmapLinearFilter,
  LinearMipmapNearestFilter,
  LinearMipmapLinearFilter,
];

/** The side of one face of a sky cube, in texels: a render target's, or its first image's; null before the images arrive. */
function skyFaceSize(sky: CubeTexture): number | null {
  const image = sky.image as { width?: number; image?: { width?: number } } | { width?: number; image?: { width?: number } }[] | undefined;
  const first = Array.isArray(image) ? image[0] : image;
  return first?.width ?? first?.image?.width ?? null;
}

/** Whether a sky cube has the mip levels a rough mirror reads (the painted sky and skies of images have; a cube of a user's own may not). */
function skyHasMipmaps(sky: CubeTexture): boolean {
  return sky.generateMipmaps && MIPMAP_FILTERS.includes(sky.minFilter);
}

/**
 * The sky as a sea of one roughness everywhere reflects it: where a wave model leaves the same
 * slopes unresolved at every pixel (the seed's), the blur of the sky is the same for every
 * pixel too, so it is worked out once, into a small cube (shaders/prefilteredSky.frag), and each
 * pixel reads it once. It is painted again only when the roughness has moved to another 64th of
 * a mip level, the sky has changed, or the sun has moved (which repaints the sky); a sea whose
 * roughness varies from pixel to pixel blends two of the sky's levels itself (skyCubeColorRough).
 * perf: one cube read a pixel instead of two, about a tenth of the default view on a software
 * rasterizer (docs/light-cost.md). Its code is fetched after the first frame (OceanMaterial), which
 * blends the two levels until it arrives: the same picture.
 */
export class PrefilteredSky {
  readonly target: WebGLCubeRenderTarget;
  /** How many times the cube has been painted: the test that it is not painted every frame reads it. */
  paintCount = 0;
  /** Whether a moved sun (a repainted sky) paints the cube again; a negative control turns it off. */
  followsSun = true;
  private readonly painter: CubePainter;
  private painted: { sky: CubeTexture; version: number; level: number; sunX: number; sunY: number; sunZ: number } | null = null;

  constructor() {
    this.target = new WebGLCubeRenderTarget(8, {
      type: UnsignedByteType,
      generateMipmaps: false,
      minFilter: LinearFilter,
      magFilter: LinearFilter,
    });
    this.target.texture.colorSpace = LinearSRGBColorSpace;
    this.target.texture.userData[SQUARE_ROOT_SKY] = true;
    this.painter = new CubePainter(this.target, fragmentShader, {
      ...createSkyCubeUniforms(this.target.texture),
      uSlopeVariance: { value: 0 },
    });
  }

  get texture(): CubeTexture {
    return this.target.texture;
  }

  /**
   * Sets an ocean material (src/render/ocean/oceanMaterial.ts) to read this cube
   * (OCEAN_PREFILTERED_SKY), painted for its sky, its sun and the sea's one unresolved
   * mean-square slope `slopeVariance`; or to blend the sky's levels itself where the slopes vary
   * by pixel (undefined), for the windless mirror and the sharp sky, and for a sky that cannot
   * be prefiltered.
   */
  prepare(material: ShaderMaterial, renderer: WebGLRenderer, slopeVariance: number | undefined): void {
    const defines = material.defines ?? {};
    const uniforms = material.uniforms;
    const shown =
      slopeVariance !== undefined &&
      !('OCEAN_SMOOTH_SEA' in defines) &&
      !('OCEAN_SHARP_SKY' in defines) &&
      this.update(renderer, uniforms.uSky.value as CubeTexture, slopeVariance, uniforms.uSunDirection.value as Vector3);
    setMaterialDefine(material, 'OCEAN_PREFILTERED_SKY', shown);
    if (shown) uniforms.uPrefilteredSky.value = this.texture;
  }

  /**
   * Paints the cube for `sky` seen in a sea of unresolved mean-square slope `slopeVariance`
   * under the sun `sun`, unless it already shows that. Returns whether the cube now shows it:
   * false for a sky without mip levels, or whose images have not arrived, which the sea then
   * reads as before.
   */
  update(renderer: WebGLRenderer, sky: CubeTexture, slopeVariance: number, sun: Vector3): boolean {
    const faceSize = skyFaceSize(sky);
    if (faceSize === null || !skyHasMipmaps(sky)) return false;
    // Rounded, the cube depends on the roughness alone, not on those it was painted for
    // before: a view reopened at the same time draws the same pixels.
    const level = Math.round(skyBlurLevel(faceSize, slopeVariance) * LEVEL_STEPS) / LEVEL_STEPS;
    const last = this.painted;
    const sunStill = !this.followsSun || (last !== null && last.sunX === sun.x && last.sunY === sun.y && last.sunZ === sun.z);
    const same = last !== null && last.sky === sky && last.version === sky.version && sunStill;
    if (same && last.level === level) return true;
    this.painted = { sky, version: sky.version, level, sunX: sun.x, sunY: sun.y, sunZ: sun.z };
    // At level 0 (a mirror, or nearly) every variance reads the sky's full resolution alike.
    const variance = level > 0 ? slopeVarianceAtLevel(faceSize, level) : slopeVariance;
    const size = prefilteredFaceSize(faceSize, variance);
    if (this.target.width !== size) this.target.setSize(size, size);
    const uniforms = this.painter.material.uniforms;
    setSkyCube(uniforms as SkyCubeUniforms, sky);
    uniforms.uSlopeVariance.value = variance;
    this.painter.paint(renderer);
    this.paintCount++;
    return true;
  }

  /** A restored WebGL context gives the cube back empty: the next update paints it again. */
  forget(): void {
    this.painted = null;
  }

  dispose(): void {
    this.target.dispose();
    this.painter.dispose();
  }
}
