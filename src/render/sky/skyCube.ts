import {
  CubeTexture,
  CubeTextureLoader,
  DataTexture,
  RGBAFormat,
  SRGBColorSpace,
  UnsignedByteType,
  LinearFilter,
  LinearMipmapNearestFilter,
} from 'three';
import { CUBE_FACES, SkyPainter } from '../../sim/optics/skyPainter';

/** The six face URLs under a base path, in three.js's loader order. */
export function skyFaceUrls(base: string): string[] {
  const prefix = base.endsWith('/') ? base : `${base}/`;
  return CUBE_FACES.map((face) => `${prefix}${face}.png`);
}

export function loadSkyCube(base: string): Promise<CubeTexture> {
  return new Promise((resolve, reject) => {
    new CubeTextureLoader().load(
      skyFaceUrls(base),
      (texture) => {
        texture.colorSpace = SRGBColorSpace;
        withBlurLevels(texture);
        resolve(texture);
      },
      undefined,
      () => reject(new Error(`The sky images under "${base}" could not be loaded.`)),
    );
  });
}

/**
 * A small sky painted in memory with the same painter as the shipped images: what the
 * ocean reflects when the sky files are missing, so the scene still reads as a sea.
 */
export function paintedSkyCube(sun: [number, number, number], size = 32): CubeTexture {
  const painter = new SkyPainter(sun);
  const faces = CUBE_FACES.map((face) => {
    return new DataTexture(painter.paintFace(face, size), size, size, RGBAFormat, UnsignedByteType);
  });
  // three.js uploads a cube whose faces are DataTextures from their pixel arrays.
  const cube = new CubeTexture(faces as unknown as HTMLImageElement[]);
  cube.format = RGBAFormat;
  cube.type = UnsignedByteType;
  cube.colorSpace = SRGBColorSpace;
  cube.magFilter = LinearFilter;
  withBlurLevels(cube);
  cube.needsUpdate = true;
  return cube;
}

/**
 * Mip levels for a sky made of images, as the painted sky has (sunSky.ts): a rough sea reads
 * the sky blurred from them (shaders/skyCube.glsl skyCubeColorRough), and without them it
 * would mirror every image sharply whatever the wind. Read one level at a time, as the painted
 * sky's (perf: for SwiftShader only, whose trilinear cube filter is slow; docs/light-sun-and-sky.md).
 */
function withBlurLevels(cube: CubeTexture): void {
  cube.generateMipmaps = true;
  cube.minFilter = LinearMipmapNearestFilter;
}
