import { Mesh, OrthographicCamera, PlaneGeometry, Scene, ShaderMaterial, type Texture, type WebGLRenderer } from 'three';
import vertexShader from '../../shaders/fullscreen.vert?raw';
import fragmentShader from '../../shaders/heightmapView.frag?raw';

/** A full-screen picture of the two ripple heightmaps: the textures the vertex shader samples. */
export class HeightmapView {
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly material: ShaderMaterial;

  constructor() {
    this.material = new ShaderMaterial({
      vertexShader,
      fragmentShader,
      uniforms: { uHeightmap0: { value: null }, uHeightmap1: { value: null }, uAspect: { value: 1 } },
      depthTest: false,
      depthWrite: false,
    });
    const quad = new Mesh(new PlaneGeometry(2, 2), this.material);
    quad.frustumCulled = false;
    this.scene.add(quad);
  }

  render(renderer: WebGLRenderer, heightmaps: readonly [Texture, Texture], aspect: number): void {
    this.material.uniforms.uHeightmap0.value = heightmaps[0];
    this.material.uniforms.uHeightmap1.value = heightmaps[1];
    this.material.uniforms.uAspect.value = aspect;
    renderer.render(this.scene, this.camera);
  }

  dispose(): void {
    for (const child of this.scene.children) (child as Mesh).geometry.dispose();
    this.material.dispose();
  }
}
