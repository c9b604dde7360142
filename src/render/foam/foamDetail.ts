import {
  LinearFilter,
  LinearMipmapLinearFilter,
  RepeatWrapping,
  ShaderMaterial,
  WebGLRenderTarget,
  type Texture,
  type WebGLRenderer,
} from 'three';
import { FullScreenQuad } from 'three/addons/postprocessing/Pass.js';
import vertexShader from '../../../shaders/fullscreen.vert?raw';
import fragmentShader from '../../../shaders/foam/foamDetail.frag?raw';
import foamMaterial from '../../../shaders/foam/foamMaterial.glsl?raw';
import { glslVec3 } from '../shaders/shaderConstants';
import { foamReflectance } from '../../sim/optics/foamReflectance';

/**
 * The foam material's GLSL (chunk `oceano_foam`, src/render/shaders/lateChunks.ts), with foam's
 * measured reflectance as FOAM_REFLECTANCE: it travels with the texture it samples.
 */
export const foamMaterialChunk = `#define FOAM_REFLECTANCE ${glslVec3(foamReflectance())}\n${foamMaterial}`;

/** Texels per side of the detail tile: 512 over FOAM_DETAIL_TILE metres is about a centimetre per texel. */
const SIZE = 512;

/**
 * The foam's detail texture (shaders/foam/foamDetail.frag): drawn once on the GPU, then only
 * sampled, mipmapped so that foam far away reads as its average rather than as sparkle. Its
 * code is fetched with the first view that draws foam (the spectral sea, the boat's wake).
 */
export class FoamDetail {
  private readonly target: WebGLRenderTarget;
  /** The tile's mean density (r), read back once it is drawn: far foam is shaded against it (foamOver). */
  meanDensity = 0.5;

  constructor(renderer: WebGLRenderer) {
    this.target = new WebGLRenderTarget(SIZE, SIZE, {
      wrapS: RepeatWrapping,
      wrapT: RepeatWrapping,
      minFilter: LinearMipmapLinearFilter,
      magFilter: LinearFilter,
      generateMipmaps: true,
      depthBuffer: false,
      stencilBuffer: false,
    });
    this.draw(renderer);
  }

  get texture(): Texture {
    return this.target.texture;
  }

  /** Draws the tile (again after a lost context: render targets do not survive one). */
  draw(renderer: WebGLRenderer): void {
    const material = new ShaderMaterial({ name: 'FoamDetail', vertexShader, fragmentShader, depthTest: false, depthWrite: false });
    const quad = new FullScreenQuad(material);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.target);
    quad.render(renderer);
    const texels = new Uint8Array(4 * SIZE * SIZE);
    renderer.readRenderTargetPixels(this.target, 0, 0, SIZE, SIZE, texels);
    renderer.setRenderTarget(previous);
    quad.dispose();
    material.dispose();
    let sum = 0;
    for (let i = 0; i < texels.length; i += 4) sum += texels[i];
    this.meanDensity = Math.max(sum / (255 * SIZE * SIZE), 1 / 255);
  }

  dispose(): void {
    this.target.dispose();
  }
}
