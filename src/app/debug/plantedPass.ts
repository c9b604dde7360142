import { Mesh, MeshBasicMaterial, OrthographicCamera, PlaneGeometry, Scene, WebGLRenderTarget, type WebGLRenderer } from 'three';

/**
 * A negative control for the frame's counts: one render more, into a small target of its own, as a
 * stray pass would be. The renderer's target is restored, and everything made here is freed.
 */
export function drawPlantedPass(renderer: WebGLRenderer): void {
  const target = new WebGLRenderTarget(4, 4, { depthBuffer: false });
  const geometry = new PlaneGeometry(2, 2);
  const material = new MeshBasicMaterial({ color: 0xff00ff });
  const scene = new Scene().add(new Mesh(geometry, material));
  const previous = renderer.getRenderTarget();
  renderer.setRenderTarget(target);
  renderer.render(scene, new OrthographicCamera(-1, 1, 1, -1, 0, 1));
  renderer.setRenderTarget(previous);
  target.dispose();
  geometry.dispose();
  material.dispose();
}
