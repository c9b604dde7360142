import { Mesh, OrthographicCamera, PlaneGeometry, Scene, ShaderMaterial, Vector2, type Texture, type WebGLRenderer } from 'three';
import type { HeightmapLayout } from '../waves/waveModelView';
import vertexShader from '../../../shaders/fullscreen.vert?raw';
import fragmentShader from '../../../shaders/heightmapView.frag?raw';

/**
 * A full-screen picture of a wave model's two heightmaps, the textures the vertex shader samples:
 * the seed's two Perlin ripple maps, or the FFT's largest and smallest cascade's height field.
 */
export class HeightmapView {
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly material: ShaderMaterial;

  constructor() {
    this.material = new ShaderMaterial({
      vertexShader,
      fragmentShader,
      uniforms: { uHeightmap0: { value: null }, uHeightmap1: { value: null }, uAspect: { value: 1 }, uChannel: { value: 0 }, uRange: { value: new Vector2(1, 1) } },
      depthTest: false,
      depthWrite: false,
    });
    const quad = new Mesh(new PlaneGeometry(2, 2), this.material);
    quad.frustumCulled = false;
    this.scene.add(quad);
  }

  render(renderer: WebGLRenderer, heightmaps: readonly [Texture, Texture], aspect: number, layout: HeightmapLayout = { channel: 0, range: [1, 1] }): void {
    const u = this.material.uniforms;
    u.uHeightmap0.value = heightmaps[0];
    u.uHeightmap1.value = heightmaps[1];
    u.uAspect.value = aspect;
    u.uChannel.value = layout.channel;
    (u.uRange.value as Vector2).set(layout.range[0], layout.range[1]);
    renderer.render(this.scene, this.camera);
  }

  dispose(): void {
    for (const child of this.scene.children) (child as Mesh).geometry.dispose();
    this.material.dispose();
  }
}
