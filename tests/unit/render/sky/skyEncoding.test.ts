import { describe, expect, it } from 'vitest';
import { CubeTexture, UnsignedByteType } from 'three';
import { SunSky } from '../../../../src/render/sky/sunSky';
import { skyFlip, skySquared } from '../../../../src/render/sky/skyCubeUniforms';
import { paintedSkyCube } from '../../../../src/render/sky/skyCube';

describe('how each sky cube is read (shaders/skyCube.glsl)', () => {
  it('the default sky cube holds square roots in 8 bits, read squared and unmirrored', () => {
    const sky = new SunSky(8);
    expect(sky.texture.type).toBe(UnsignedByteType);
    expect(skySquared(sky.texture)).toBe(1);
    expect(skyFlip(sky.texture)).toBe(1);
    sky.dispose();
  });

  it('cubes made from images or painted on the CPU hold the colour itself, read as is and mirrored', () => {
    expect(skySquared(new CubeTexture())).toBe(0);
    expect(skyFlip(new CubeTexture())).toBe(-1);
    expect(skySquared(paintedSkyCube([0, 0.5, -0.8]))).toBe(0);
  });
});
