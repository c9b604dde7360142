import {
  BufferAttribute,
  BufferGeometry,
  FloatType,
  GLSL3,
  Mesh,
  NearestFilter,
  OrthographicCamera,
  RawShaderMaterial,
  RedFormat,
  ClampToEdgeWrapping,
  Color,
  RGBAFormat,
  Scene,
  Vector2,
  Vector4,
  WebGLRenderTarget,
  type DataTexture,
  type Texture,
  type WebGLRenderer,
} from 'three';
import quadVertex from '../../../shaders/fftQuad.vert?raw';
import stepFragment from '../../../shaders/iwaveStep.frag?raw';
import disturbFragment from '../../../shaders/iwaveDisturb.frag?raw';
import scrollFragment from '../../../shaders/iwaveScroll.frag?raw';
import { BUMP_REACH, GRAVITY, IWAVE_SPONGE, type Disturbance, type SpongeLayer } from '../../sim/iwave/iwaveGrid';
import {
  fittedVerticalDerivativeKernel,
  IWAVE_KERNEL_ORBITS,
  IWAVE_KERNEL_RADIUS,
  kernelOrbitWeights,
  type ConvolutionKernel,
} from '../../sim/iwave/verticalDerivativeKernel';
import { hullSources, type MovingHull } from '../../sim/iwave/movingHull';
import { forwardOf } from '../../sim/boat/boatPose';
import { floatTexture } from '../optics/dataTextures';

export interface GpuIWaveOptions {
  /** Texels along each side (at least 256 for the app: 128 m at 0.5 m). */
  n: number;
  /** Metres per texel. */
  spacing: number;
  kernel?: ConvolutionKernel;
  /** A second kernel for the texels right of the middle, a sponge lining the middle (IWaveGrid's rightKernel). */
  rightKernel?: ConvolutionKernel | null;
  /** Light damping everywhere, 1/s. */
  damping?: number;
  sponge?: SpongeLayer;
}

function heightTarget(n: number): WebGLRenderTarget {
  return new WebGLRenderTarget(n, n, {
    type: FloatType,
    format: RGBAFormat,
    minFilter: NearestFilter,
    magFilter: NearestFilter,
    wrapS: ClampToEdgeWrapping,
    wrapT: ClampToEdgeWrapping,
    depthBuffer: false,
    stencilBuffer: false,
    generateMipmaps: false,
  });
}

/**
 * iWave on the GPU: the twin of IWaveGrid (src/sim/iwave/iwaveGrid.ts), which the parity test
 * holds it to. Two RGBA32F render targets ping-pong; texel (i, j) holds (h now, h one step
 * ago) at x = cx + (i + ½ − n/2)·Δx, z = cz + (j + ½ − n/2)·Δx. Each step is one full-screen
 * pass (shaders/iwaveStep.frag: the 13 × 13 convolution, the damped time step, the sponge and
 * the obstacle mask); a disturbance and a scroll are one pass each.
 */
export class GpuIWave {
  readonly n: number;
  readonly spacing: number;
  readonly gravity = GRAVITY;
  /** World (x, z) of the grid's centre: moved only by whole texels (recentre). */
  centerX = 0;
  centerZ = 0;
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly mesh: Mesh;
  private readonly targets: [WebGLRenderTarget, WebGLRenderTarget];
  private current = 0;
  private hull: MovingHull | null = null;
  private readonly obstacleData: Float32Array;
  private readonly obstacleTexture: DataTexture;
  private readonly stepMaterial: RawShaderMaterial;
  private readonly disturbMaterial: RawShaderMaterial;
  private readonly scrollMaterial: RawShaderMaterial;

  constructor(renderer: WebGLRenderer, options: GpuIWaveOptions) {
    if (!renderer.extensions.has('EXT_color_buffer_float'))
      throw new Error('Interactive waves need WebGL2 float render targets (EXT_color_buffer_float).');
    this.renderer = renderer;
    const { n, spacing } = options;
    this.n = n;
    this.spacing = spacing;
    this.obstacleData = new Float32Array(n * n).fill(1);
    this.obstacleTexture = floatTexture(this.obstacleData, n, n, RedFormat, ClampToEdgeWrapping);
    this.targets = [heightTarget(n), heightTarget(n)];
    const sponge = options.sponge ?? IWAVE_SPONGE;
    const orbits = IWAVE_KERNEL_ORBITS;
    const pass = (name: string, fragmentShader: string, uniforms: Record<string, { value: unknown }>) =>
      new RawShaderMaterial({
        name,
        glslVersion: GLSL3,
        vertexShader: quadVertex,
        fragmentShader,
        uniforms,
        depthTest: false,
        depthWrite: false,
      });
    const stepText = `#define IWAVE_KERNEL_RADIUS ${IWAVE_KERNEL_RADIUS}\n#define IWAVE_ORBITS ${orbits}\n${stepFragment}`;
    this.stepMaterial = pass('IWaveStep', stepText, {
      uHeights: { value: null },
      uObstacle: { value: this.obstacleTexture },
      uWeights: { value: new Float32Array(orbits) },
      uRightWeights: { value: new Float32Array(orbits) },
      uSplit: { value: false },
      uN: { value: n },
      uKick: { value: 0 },
      uDt: { value: 0 },
      uDamping: { value: options.damping ?? 0 },
      uSponge: { value: new Vector2(sponge.width, sponge.strength) },
      uHull: { value: new Vector4() },
      uHullShape: { value: new Vector4() },
      uHullSources: { value: new Vector4() },
      uReach: { value: BUMP_REACH },
    });
    this.setKernels(options.kernel ?? fittedVerticalDerivativeKernel(), options.rightKernel ?? null);
    this.disturbMaterial = pass('IWaveDisturb', disturbFragment, {
      uHeights: { value: null },
      uObstacle: { value: this.obstacleTexture },
      uCentre: { value: new Vector2() },
      uRadius: { value: 1 },
      uHeight: { value: 0 },
      uReach: { value: BUMP_REACH },
    });
    this.scrollMaterial = pass('IWaveScroll', scrollFragment, {
      uHeights: { value: null },
      uN: { value: n },
      uShift: { value: new Vector2() },
    });
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), 3));
    this.mesh = new Mesh(geometry, this.stepMaterial);
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
    this.clear();
  }

  /** (h now, h one step ago) per texel: RGBA32F, read with texelFetch. */
  get texture(): Texture {
    return this.targets[this.current].texture;
  }

  /** The render target holding the field now (for read-backs). */
  get target(): WebGLRenderTarget {
    return this.targets[this.current];
  }

  /** Calm water everywhere. */
  clear(): void {
    const previous = this.renderer.getRenderTarget();
    const colour = this.renderer.getClearColor(new Color());
    const alpha = this.renderer.getClearAlpha();
    this.renderer.setClearColor(0x000000, 0);
    for (const target of this.targets) {
      this.renderer.setRenderTarget(target);
      this.renderer.clear(true, false, false);
    }
    this.renderer.setClearColor(colour, alpha);
    this.renderer.setRenderTarget(previous);
  }

  /** Sets the obstacle mask (1 water, 0 solid; n × n, row by row along z), uploaded at once. */
  setObstacle(mask: ArrayLike<number>): void {
    this.obstacleData.set(mask);
    this.obstacleTexture.needsUpdate = true;
  }

  /** Adds a bump at rest at world (x, z) (IWaveGrid.disturb). */
  disturb(d: Disturbance): void {
    const u = this.disturbMaterial.uniforms;
    (u.uCentre.value as Vector2).set(...this.texelOf(d.x, d.z));
    u.uRadius.value = d.radius / this.spacing;
    u.uHeight.value = d.height;
    this.run(this.disturbMaterial);
  }

  /** The kernel of every texel, or `left`'s left of the middle and `right`'s right of it, a sponge lining the middle. */
  setKernels(left: ConvolutionKernel, right: ConvolutionKernel | null): void {
    const u = this.stepMaterial.uniforms;
    (u.uWeights.value as Float32Array).set(kernelOrbitWeights(left));
    (u.uRightWeights.value as Float32Array).set(right ? kernelOrbitWeights(right) : kernelOrbitWeights(left));
    u.uSplit.value = right !== null;
  }

  /** The boat during the next steps (IWaveGrid.hull): its footprint solid, its bow and stern sources; null for none. */
  setHull(hull: MovingHull | null): void {
    this.hull = hull;
  }

  /** Advances the field by one step of `dt` seconds. */
  step(dt: number): void {
    const u = this.stepMaterial.uniforms;
    u.uKick.value = (this.gravity * dt * dt) / this.spacing;
    u.uDt.value = dt;
    const hull = this.hull;
    const shape = u.uHullShape.value as Vector4;
    if (hull) {
      const [bow, stern] = hullSources(hull);
      (u.uHull.value as Vector4).set(...this.texelOf(hull.x, hull.z), ...forwardOf(hull.heading));
      shape.set((0.5 * hull.length) / this.spacing, (0.5 * hull.beam) / this.spacing, bow.radius / this.spacing, bow.rate * dt);
      (u.uHullSources.value as Vector4).set(...this.texelOf(bow.x, bow.z), ...this.texelOf(stern.x, stern.z));
    } else {
      shape.set(0, 0, 1, 0);
    }
    this.run(this.stepMaterial);
  }

  /** World (x, z) in texel units: texel (i, j)'s centre is (i, j). */
  private texelOf(x: number, z: number): [number, number] {
    return [(x - this.centerX) / this.spacing + this.n / 2 - 0.5, (z - this.centerZ) / this.spacing + this.n / 2 - 0.5];
  }

  /**
   * Moves the grid so that its centre is the texel-aligned point nearest (x, z): the field
   * stays where it is in the world, and what comes in over the edge is calm. Returns the
   * whole texels moved along x and z.
   */
  recentre(x: number, z: number): [number, number] {
    const di = Math.round((x - this.centerX) / this.spacing);
    const dj = Math.round((z - this.centerZ) / this.spacing);
    if (di === 0 && dj === 0) return [0, 0];
    (this.scrollMaterial.uniforms.uShift.value as Vector2).set(di, dj);
    this.run(this.scrollMaterial);
    this.centerX += di * this.spacing;
    this.centerZ += dj * this.spacing;
    return [di, dj];
  }

  /** Draws `material` over the other target, reading the current one, and makes it current. */
  private run(material: RawShaderMaterial): void {
    material.uniforms.uHeights.value = this.texture;
    const write = this.targets[1 - this.current];
    const previous = this.renderer.getRenderTarget();
    const autoClear = this.renderer.autoClear;
    this.renderer.autoClear = false;
    this.mesh.material = material;
    this.renderer.setRenderTarget(write);
    this.renderer.render(this.scene, this.camera);
    this.renderer.setRenderTarget(previous);
    this.renderer.autoClear = autoClear;
    this.current = 1 - this.current;
  }

  dispose(): void {
    for (const target of this.targets) target.dispose();
    this.obstacleTexture.dispose();
    this.stepMaterial.dispose();
    this.disturbMaterial.dispose();
    this.scrollMaterial.dispose();
    this.mesh.geometry.dispose();
  }
}
