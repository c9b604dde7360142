import {
  Mesh,
  OrthographicCamera,
  PlaneGeometry,
  Scene,
  ShaderMaterial,
  Vector2,
  Vector3,
  Vector4,
  type CubeTexture,
  type WebGLRenderer,
} from 'three';
import type { Rect } from '../../sim/layout/rect';
import { CROSS_CELLS } from '../../sim/optics/cubeCross';
import { createSkyCubeUniforms, setSkyCube, type SkyCubeUniforms } from '../sky/skyCubeUniforms';
import { resolveChunks } from '../shaders/shaderChunks';
import vertexShader from '../../../shaders/fullscreen.vert?raw';
import fragmentShader from '../../../shaders/cubeCross.frag?raw';

/**
 * The sky's cube map itself, before the sea reflects it: its six faces unfolded into a
 * cross (src/sim/optics/cubeCross.ts says which face goes where, and the shader reads the
 * same table), drawn on a full-canvas quad.
 */
export class CubeCrossFigure {
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly material: ShaderMaterial;

  constructor(sky: CubeTexture) {
    this.material = new ShaderMaterial({
      vertexShader,
      fragmentShader: resolveChunks(fragmentShader),
      uniforms: {
        ...createSkyCubeUniforms(sky),
        uBox: { value: new Vector4() },
        uCellPlace: { value: CROSS_CELLS.map((c) => new Vector2(c.column, c.row)) },
        uCellCentre: { value: CROSS_CELLS.map((c) => new Vector3(...c.centre)) },
        uCellRight: { value: CROSS_CELLS.map((c) => new Vector3(...c.right)) },
        uCellUp: { value: CROSS_CELLS.map((c) => new Vector3(...c.up)) },
      },
      depthTest: false,
      depthWrite: false,
    });
    const quad = new Mesh(new PlaneGeometry(2, 2), this.material);
    quad.frustumCulled = false;
    this.scene.add(quad);
  }

  /** `box`: the cross, CSS px in a canvas of CSS size `canvas`; `sky`: the cube the sea reflects now. */
  render(renderer: WebGLRenderer, sky: CubeTexture, box: Rect, canvas: { width: number; height: number }): void {
    const u = this.material.uniforms;
    if (u.uSky.value !== sky) setSkyCube(u as SkyCubeUniforms, sky);
    (u.uBox.value as Vector4).set(
      box.x / canvas.width,
      1 - (box.y + box.height) / canvas.height,
      (box.x + box.width) / canvas.width,
      1 - box.y / canvas.height,
    );
    renderer.render(this.scene, this.camera);
  }

  dispose(): void {
    for (const child of this.scene.children) (child as Mesh).geometry.dispose();
    this.material.dispose();
  }
}
