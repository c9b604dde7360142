import type { CubeTexture, IUniform } from 'three';

/**
 * The uniforms of shaders/skyCube.glsl (`#include <oceano_sky_cube>`): the cube and how to read
 * it. Every shader that reads the sky takes this set, and setSkyCube keeps the three together.
 */
export type SkyCubeUniforms = Record<'uSky' | 'uSkyFlip' | 'uSkySquared', IUniform>;

/** Marks a cube whose texels hold the square root of the colour (the default sky's, src/render/sky/sunSky.ts). */
export const SQUARE_ROOT_SKY = 'oceanoSquareRootSky';

/**
 * three.js stores cube maps made from images mirrored in x (its flipEnvMap convention),
 * while a cube render target holds each world direction where it is: -1 and +1.
 */
export function skyFlip(sky: CubeTexture): number {
  return sky.isRenderTargetTexture ? 1 : -1;
}

/** 1 where the cube holds square roots, 0 where it holds the colour (image cubes). */
export function skySquared(sky: CubeTexture): number {
  return sky.userData[SQUARE_ROOT_SKY] === true ? 1 : 0;
}

export function createSkyCubeUniforms(sky: CubeTexture): SkyCubeUniforms {
  return { uSky: { value: sky }, uSkyFlip: { value: skyFlip(sky) }, uSkySquared: { value: skySquared(sky) } };
}

export function setSkyCube(uniforms: SkyCubeUniforms, sky: CubeTexture): void {
  uniforms.uSky.value = sky;
  uniforms.uSkyFlip.value = skyFlip(sky);
  uniforms.uSkySquared.value = skySquared(sky);
}
