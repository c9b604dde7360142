import {
  BufferAttribute,
  BufferGeometry,
  FloatType,
  NearestFilter,
  OrthographicCamera,
  Points,
  RGBAFormat,
  Scene,
  ShaderMaterial,
  Vector2,
  WebGLRenderTarget,
  type Texture,
  type WebGLRenderer,
} from 'three';
import vertexShader from '../../shaders/probe.vert?raw';
import fragmentShader from '../../shaders/probe.frag?raw';
import type { SurfaceState } from '../sim/surface';
import type { SurfaceSample } from '../sim/oceanSurface';
import { registerShaderChunks } from './shaderChunks';
import { applyHeightmaps, applySurfaceState, createSurfaceUniforms, type SurfaceUniforms } from './surfaceUniforms';

const TARGET_WIDTH = 256;

/**
 * Runs the real displacement shader on the GPU for a list of points and reads the results
 * back from a float render target: the GPU side of the CPU-vs-GPU parity check.
 */
export class SurfaceProbe {
  private readonly material: ShaderMaterial;
  private readonly camera = new OrthographicCamera();

  constructor(private readonly renderer: WebGLRenderer) {
    registerShaderChunks();
    this.material = new ShaderMaterial({
      vertexShader,
      fragmentShader,
      uniforms: { ...createSurfaceUniforms(), uTargetSize: { value: new Vector2() } },
      depthTest: false,
      depthWrite: false,
    });
  }

  probe(points: readonly (readonly [number, number])[], state: SurfaceState, heightmaps: [Texture, Texture]): SurfaceSample[] {
    const count = points.length;
    if (count === 0) return [];
    const rows = Math.ceil(count / TARGET_WIDTH);
    const samples = new Float32Array(count * 2);
    const indices = new Float32Array(count);
    points.forEach(([x, z], i) => {
      samples[i * 2] = x;
      samples[i * 2 + 1] = z;
      indices[i] = i;
    });
    const geometry = new BufferGeometry();
    geometry.setAttribute('aSample', new BufferAttribute(samples, 2));
    geometry.setAttribute('aIndex', new BufferAttribute(indices, 1));
    // three needs a position attribute to know the draw count; the shader ignores it.
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(count * 3), 3));
    const target = new WebGLRenderTarget(TARGET_WIDTH, rows, {
      type: FloatType,
      format: RGBAFormat,
      minFilter: NearestFilter,
      magFilter: NearestFilter,
      depthBuffer: false,
    });
    const uniforms = this.material.uniforms as SurfaceUniforms & { uTargetSize: { value: Vector2 } };
    applySurfaceState(uniforms, state);
    applyHeightmaps(uniforms, heightmaps);
    uniforms.uTargetSize.value.set(TARGET_WIDTH, rows);

    const scene = new Scene();
    const points3 = new Points(geometry, this.material);
    points3.frustumCulled = false;
    scene.add(points3);

    const previousTarget = this.renderer.getRenderTarget();
    const pixels = new Float32Array(TARGET_WIDTH * rows * 4);
    try {
      this.renderer.setRenderTarget(target);
      this.renderer.render(scene, this.camera);
      this.renderer.readRenderTargetPixels(target, 0, 0, TARGET_WIDTH, rows, pixels);
    } finally {
      this.renderer.setRenderTarget(previousTarget);
      geometry.dispose();
      target.dispose();
    }
    return Array.from({ length: count }, (_, i) => ({
      height: pixels[i * 4],
      normal: [pixels[i * 4 + 1], pixels[i * 4 + 2], pixels[i * 4 + 3]] as [number, number, number],
    }));
  }

  dispose(): void {
    this.material.dispose();
  }
}
