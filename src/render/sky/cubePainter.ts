import {
  BackSide,
  BoxGeometry,
  CubeCamera,
  Mesh,
  Scene,
  ShaderMaterial,
  type IUniform,
  type WebGLCubeRenderTarget,
  type WebGLRenderer,
} from 'three';
import vertexShader from '../../../shaders/skyDome.vert?raw';
import { resolveChunks } from '../shaders/shaderChunks';

/**
 * Paints a cube render target with a fragment shader that is given, for each texel, the world
 * direction from the cube's centre through it (shaders/skyDome.vert): a box around a cube
 * camera, seen from inside. The sky painted from the sun (sunSky.ts) and the sky blurred for a
 * rough sea (prefilteredSky.ts) are painted this way.
 */
export class CubePainter {
  readonly material: ShaderMaterial;
  private readonly scene = new Scene();
  private readonly camera: CubeCamera;
  private readonly box = new BoxGeometry(2, 2, 2);

  constructor(target: WebGLCubeRenderTarget, fragmentShader: string, uniforms: Record<string, IUniform>) {
    this.material = new ShaderMaterial({
      vertexShader,
      fragmentShader: resolveChunks(fragmentShader),
      side: BackSide,
      depthTest: false,
      depthWrite: false,
      uniforms,
    });
    this.scene.add(new Mesh(this.box, this.material));
    this.camera = new CubeCamera(0.1, 10, target);
  }

  /** Paints the six faces (six passes into the target). */
  paint(renderer: WebGLRenderer): void {
    this.camera.update(renderer, this.scene);
  }

  dispose(): void {
    this.material.dispose();
    this.box.dispose();
  }
}
