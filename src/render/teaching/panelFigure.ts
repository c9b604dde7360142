import { Mesh, OrthographicCamera, PlaneGeometry, Scene, ShaderMaterial, Vector4, type Texture, type WebGLRenderer } from 'three';
import type { Rect } from '../../sim/layout/rect';
import vertexShader from '../../../shaders/fullscreen.vert?raw';
import fragmentShader from '../../../shaders/panelFigure.frag?raw';

/** One square of the figure: a height field as grey, or the mix (1 − weight)·first + weight·second of two. */
export interface Panel {
  /** CSS px in the canvas, from its top left. */
  rect: Rect;
  first: Texture;
  second?: Texture;
  weight?: number;
  /** The height drawn white (its negative black). */
  range?: number;
}

const MAX_PANELS = 3;

/**
 * Up to three greyscale pictures of height fields side by side on a full-canvas quad: the
 * heightmaps the vertex shader samples, the steps of the Perlin noise that makes them.
 */
export class PanelFigure {
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly material: ShaderMaterial;

  constructor() {
    const uniforms: Record<string, { value: unknown }> = {
      uCount: { value: 0 },
      uRect: { value: Array.from({ length: MAX_PANELS }, () => new Vector4()) },
      uWeight: { value: new Array<number>(MAX_PANELS).fill(0) },
      uRange: { value: new Array<number>(MAX_PANELS).fill(1) },
      uChannel: { value: 0 },
    };
    for (let i = 0; i < MAX_PANELS; i++) {
      uniforms[`uFirst${i}`] = { value: null };
      uniforms[`uSecond${i}`] = { value: null };
    }
    this.material = new ShaderMaterial({ vertexShader, fragmentShader, uniforms, depthTest: false, depthWrite: false });
    const quad = new Mesh(new PlaneGeometry(2, 2), this.material);
    quad.frustumCulled = false;
    this.scene.add(quad);
  }

  /** `canvas`: the canvas's CSS size; `channel`: where each texel holds its height (0: r, 1: g). */
  render(renderer: WebGLRenderer, panels: readonly Panel[], canvas: { width: number; height: number }, channel: 0 | 1 = 0): void {
    const u = this.material.uniforms;
    u.uCount.value = Math.min(MAX_PANELS, panels.length);
    u.uChannel.value = channel;
    panels.slice(0, MAX_PANELS).forEach((panel, i) => {
      const { x, y, width, height } = panel.rect;
      // Fractions of the canvas with y upwards, as vUv runs.
      (u.uRect.value as Vector4[])[i].set(
        x / canvas.width,
        1 - (y + height) / canvas.height,
        (x + width) / canvas.width,
        1 - y / canvas.height,
      );
      (u.uWeight.value as number[])[i] = panel.second ? (panel.weight ?? 0) : 0;
      (u.uRange.value as number[])[i] = panel.range ?? 1;
      u[`uFirst${i}`].value = panel.first;
      u[`uSecond${i}`].value = panel.second ?? panel.first;
    });
    renderer.render(this.scene, this.camera);
  }

  dispose(): void {
    for (const child of this.scene.children) (child as Mesh).geometry.dispose();
    this.material.dispose();
  }
}
