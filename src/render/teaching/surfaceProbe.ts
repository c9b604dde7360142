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
  type WebGLRenderer,
} from 'three';
import vertexShader from '../../../shaders/probe.vert?raw';
import fragmentShader from '../../../shaders/probe.frag?raw';
import type { SurfaceSample } from '../../sim/waves/waveModel';
import type { WaveBinding } from '../waves/waveBinding';
import type { WakeUniforms } from '../wake/wakeUniforms';
import type { InteractiveWaveUniforms } from '../iwave/interactiveWaveUniforms';
import { setMaterialDefine } from '../shaders/materialDefines';
import { wakeChunk } from '../wake/wakeChunk';
import type { CoastUniforms } from '../coast/coastUniforms';

const TARGET_WIDTH = 256;

/** What the GPU computed at one grid point: the chunk's waveDisplacement and waveNormal (with the wake and the interactive waves where they are on). */
export interface ProbeSample extends SurfaceSample {
  /** waveDisplacement(gridXZ): where the grid point goes, metres. `height` is its dy. */
  displacement: [number, number, number];
  /** On the spectral sea, the windrows' share of the foam left behind at the grid point, for a group share of 0; 0 on the other seas. */
  windrowShare: number;
}

/**
 * Runs the active wave model's real shader chunk on the GPU for a list of grid points and
 * reads the results back from a float render target: the GPU side of the CPU-vs-GPU
 * parity check. The caller sets the model's uniforms for the time wanted (update(time)).
 */
export class SurfaceProbe {
  private readonly material: ShaderMaterial;
  private readonly camera = new OrthographicCamera();

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly waves: WaveBinding,
    wake: WakeUniforms,
    interactive: InteractiveWaveUniforms,
  ) {
    // probe.vert adds the wake wherever it is on: its GLSL comes with this code.
    waves.late.provide('oceano_wake', wakeChunk);
    this.material = waves.attach(
      new ShaderMaterial({
        vertexShader,
        fragmentShader,
        uniforms: { uTargetSize: { value: new Vector2() }, ...wake, ...interactive },
        depthTest: false,
        depthWrite: false,
      }),
    );
    // The windrows' field is read at every wind here, for its parity check (probe.vert).
    setMaterialDefine(this.material, 'OCEAN_WINDROWS', true);
  }

  /** Whether the interactive waves are added (their chunk must have reached the binding first). */
  setInteractiveWavesOn(on: boolean): void {
    setMaterialDefine(this.material, 'OCEAN_IWAVE', on);
  }

  /** The coast's uniforms while there is a coast (its chunk has reached the binding): its swell and calmed wind sea are added; null: none. */
  setCoast(uniforms: CoastUniforms | null): void {
    if (uniforms) Object.assign(this.material.uniforms, uniforms);
    setMaterialDefine(this.material, 'OCEAN_COAST', uniforms !== null);
  }

  probe(points: readonly (readonly [number, number])[]): ProbeSample[] {
    const count = points.length;
    if (count === 0) return [];
    // Two texels per point: the displacement, then the normal.
    const texels = count * 2;
    const rows = Math.ceil(texels / TARGET_WIDTH);
    const samples = new Float32Array(texels * 2);
    const indices = new Float32Array(texels);
    points.forEach(([x, z], i) => {
      for (let k = 0; k < 2; k++) {
        samples[(2 * i + k) * 2] = x;
        samples[(2 * i + k) * 2 + 1] = z;
        indices[2 * i + k] = 2 * i + k;
      }
    });
    const geometry = new BufferGeometry();
    geometry.setAttribute('aSample', new BufferAttribute(samples, 2));
    geometry.setAttribute('aIndex', new BufferAttribute(indices, 1));
    // three needs a position attribute to know the draw count; the shader ignores it.
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(texels * 3), 3));
    const target = new WebGLRenderTarget(TARGET_WIDTH, rows, {
      type: FloatType,
      format: RGBAFormat,
      minFilter: NearestFilter,
      magFilter: NearestFilter,
      depthBuffer: false,
    });
    (this.material.uniforms.uTargetSize.value as Vector2).set(TARGET_WIDTH, rows);

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
    return Array.from({ length: count }, (_, i) => {
      const d = i * 8;
      return {
        displacement: [pixels[d], pixels[d + 1], pixels[d + 2]] as [number, number, number],
        height: pixels[d + 1],
        normal: [pixels[d + 4], pixels[d + 5], pixels[d + 6]] as [number, number, number],
        windrowShare: pixels[d + 7],
      };
    });
  }

  dispose(): void {
    this.waves.detach(this.material);
    this.material.dispose();
  }
}
