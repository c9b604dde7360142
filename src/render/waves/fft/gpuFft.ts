import {
  BufferAttribute,
  BufferGeometry,
  DataTexture,
  FloatType,
  GLSL3,
  LinearFilter,
  Mesh,
  NearestFilter,
  OrthographicCamera,
  RawShaderMaterial,
  RepeatWrapping,
  RGBAFormat,
  Scene,
  WebGLRenderTarget,
  Vector3,
  type Texture,
  type WebGLRenderer,
} from 'three';
import quadVertex from '../../../../shaders/fftQuad.vert?raw';
import spectrumSource from '../../../../shaders/fftSpectrum.frag?raw';
import sinTurns from '../../../../shaders/sinTurns.glsl?raw';
import stageFragment from '../../../../shaders/fftStage.frag?raw';
import { timeInPeriod } from '../../../sim/waves/dispersion';
import { stockhamRadices } from '../../../sim/waves/fft/stockhamFft';
import type { FftOceanSetup } from '../../../sim/waves/fft/fftOcean';
import { REPEAT_PERIOD, type SpectralTile } from '../../../sim/waves/spectra/initialSpectrum';
import { floatTexture } from '../../optics/dataTextures';

/** The spectrum's shader with the shared sine inlined: resolved here, not through three's global ShaderChunk. */
const spectrumFragment = spectrumSource.replace('#include <oceano_sin_turns>', sinTurns);

/**
 * Two RGBA32F colour attachments, written together by every pass (MRT). Needs EXT_color_buffer_float.
 * `filtered`: LINEAR, for the ocean's pixels' filtered reads (shaders/waves/fft.glsl); texelFetch ignores it.
 */
function mrtTarget(n: number, filtered = false): WebGLRenderTarget {
  const filter = filtered ? LinearFilter : NearestFilter;
  const target = new WebGLRenderTarget(n, n, {
    count: 2,
    type: FloatType,
    format: RGBAFormat,
    minFilter: filter,
    magFilter: filter,
    wrapS: RepeatWrapping,
    wrapT: RepeatWrapping,
    depthBuffer: false,
    stencilBuffer: false,
    generateMipmaps: false,
  });
  return target;
}

/** (cos, sin) of 2π q/n for q < n (a radix-4 stage reads up to 3·(n/4 − 1)), in float64 then rounded once to float32. */
function twiddleTable(n: number): DataTexture {
  const data = new Float32Array(4 * n);
  for (let q = 0; q < n; q++) {
    data[4 * q] = Math.cos((2 * Math.PI * q) / n);
    data[4 * q + 1] = Math.sin((2 * Math.PI * q) / n);
  }
  return floatTexture(data, n, 1, RGBAFormat, RepeatWrapping);
}

/**
 * GPU inverse 2-D FFTs of n × n grids, four complex signals at a time (two RGBA32F textures),
 * by Stockham passes ping-ponging between two MRT render targets: per axis the stages of
 * stockhamRadices(n) (src/sim/waves/fft/stockhamFft.ts, its CPU mirror), radix 4 where it fits and one
 * radix-2 stage for odd log₂n: 8 passes for 128² instead of 14 radix-2 passes. The result lands
 * in `target` (the same number of passes per axis, so the count is even), so callers can keep
 * its textures bound.
 */
export class GpuInverseFft {
  readonly n: number;
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly mesh: Mesh;
  /** The stage material of each radix (shaders/fftStage.frag, RADIX_4 for 4): compiled apart rather than branched on (perf: see setMaterialDefine). */
  private readonly stages: Map<number, RawShaderMaterial>;
  private readonly radices: number[];
  private readonly twiddle: DataTexture;
  private readonly scratch: WebGLRenderTarget;

  /** `radices`: the stages per axis, stockhamRadices(n) unless a test asks for others (all 2: the radix-2 passes). */
  constructor(
    private readonly renderer: WebGLRenderer,
    n: number,
    radices?: readonly number[],
  ) {
    if (!renderer.extensions.has('EXT_color_buffer_float'))
      throw new Error('The spectral ocean needs WebGL2 float render targets (EXT_color_buffer_float).');
    this.n = n;
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), 3));
    this.twiddle = twiddleTable(n);
    this.radices = [...(radices ?? stockhamRadices(n))];
    if (this.radices.reduce((a, b) => a * b, 1) !== n)
      throw new RangeError(`The radices ${this.radices.join(', ')} do not multiply to ${n}.`);
    const twiddle = this.twiddle;
    const stage = (radix: number): RawShaderMaterial =>
      new RawShaderMaterial({
        name: `FftStageRadix${radix}`,
        glslVersion: GLSL3,
        vertexShader: quadVertex,
        fragmentShader: stageFragment,
        defines: radix === 4 ? { RADIX_4: '' } : {},
        uniforms: {
          uInput0: { value: null },
          uInput1: { value: null },
          uTwiddle: { value: twiddle },
          uN: { value: n },
          uHalfSize: { value: 1 },
          uVertical: { value: false },
        },
        depthTest: false,
        depthWrite: false,
      });
    this.stages = new Map([...new Set(this.radices)].map((radix) => [radix, stage(radix)]));
    this.mesh = new Mesh(geometry, this.stages.get(this.radices[0]));
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
    this.scratch = mrtTarget(n);
  }

  /** A render target the FFT can write its result into (LINEAR-filtered when `filtered`). */
  createTarget(filtered = false): WebGLRenderTarget {
    return mrtTarget(this.n, filtered);
  }

  /** Draws `material` over every texel of `target` (any size). Leaves the renderer's own target as it was. */
  draw(material: RawShaderMaterial, target: WebGLRenderTarget): void {
    const previous = this.renderer.getRenderTarget();
    const autoClear = this.renderer.autoClear;
    this.renderer.autoClear = false;
    this.mesh.material = material;
    this.renderer.setRenderTarget(target);
    this.renderer.render(this.scene, this.camera);
    this.renderer.setRenderTarget(previous);
    this.renderer.autoClear = autoClear;
  }

  /** Reads an n × n float target back into `rgba` (4 n² values), for diagnostics. */
  read(target: WebGLRenderTarget, rgba: Float32Array): void {
    this.renderer.readRenderTargetPixels(target, 0, 0, this.n, this.n, rgba);
  }

  /** Inverse-transforms the two textures (rows, then columns) into `target`. */
  transform(input0: Texture, input1: Texture, target: WebGLRenderTarget): void {
    let source: [Texture, Texture] = [input0, input1];
    let write = this.scratch;
    for (const vertical of [false, true]) {
      let halfSize = 1;
      for (const radix of this.radices) {
        const stage = this.stages.get(radix) as RawShaderMaterial;
        const u = stage.uniforms;
        u.uInput0.value = source[0];
        u.uInput1.value = source[1];
        u.uHalfSize.value = halfSize;
        u.uVertical.value = vertical;
        this.draw(stage, write);
        halfSize *= radix;
        source = [write.textures[0], write.textures[1]];
        write = write === this.scratch ? target : this.scratch;
      }
    }
  }

  dispose(): void {
    for (const stage of this.stages.values()) stage.dispose();
    this.twiddle.dispose();
    this.scratch.dispose();
    this.mesh.geometry.dispose();
  }
}

/** h₀(k) and h₀(−k) side by side, and ω as whole cycles m per repeat period (split as in fftSpectrum.frag: 4096·mh, ml, m), as float32 textures. */
function spectrumTextures(tile: SpectralTile): { h0: DataTexture; cycles: DataTexture } {
  const n = tile.n;
  const pairs = new Float32Array(4 * n * n);
  const cycles = new Float32Array(4 * n * n);
  const omega0 = (2 * Math.PI) / REPEAT_PERIOD;
  for (let b = 0; b < n; b++) {
    for (let a = 0; a < n; a++) {
      const i = b * n + a;
      const j = ((n - b) % n) * n + ((n - a) % n);
      pairs[4 * i] = tile.h0[2 * i];
      pairs[4 * i + 1] = tile.h0[2 * i + 1];
      pairs[4 * i + 2] = tile.h0[2 * j];
      pairs[4 * i + 3] = tile.h0[2 * j + 1];
      const m = Math.round(tile.omega[i] / omega0);
      if (m >= 2 ** 24) throw new Error('A wave too fast for the float32 phase split (m ≥ 2²⁴).');
      const low = m % 4096;
      cycles[4 * i] = m - low;
      cycles[4 * i + 1] = low;
      cycles[4 * i + 2] = m;
    }
  }
  return { h0: floatTexture(pairs, n, n, RGBAFormat, RepeatWrapping), cycles: floatTexture(cycles, n, n, RGBAFormat, RepeatWrapping) };
}

/**
 * f ∈ [0, 1) as x + y + z with x and y of 12 significant bits each (exact multiples of 2⁻¹² and
 * 2⁻²⁴) and z the float32 rest, so the shader's products m·x, m·y are exact (fftSpectrum.frag).
 */
export function splitFraction(f: number): [number, number, number] {
  const x = Math.floor(f * 4096) / 4096;
  const y = Math.floor((f - x) * 2 ** 24) / 2 ** 24;
  return [x, y, Math.fround(f - x - y)];
}

/**
 * The spectral ocean on the GPU: per cascade, h₀ uploaded once (drawn on the CPU from the
 * seed, the same numbers as the CPU twin), then each update(t) one time-evolution pass and
 * the FFT passes (2·⌈log₂n / 2⌉: radix 4, GpuInverseFft). After update, per cascade c:
 *   displacement[c]: RGBA32F n × n, (dx, dy, dz, ∂Dx/∂x)
 *   derivatives[c]:  RGBA32F n × n, (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
 * Texel (p, q) is the grid point x = p·L/n, z = q·L/n of a tile of side L = sizes[c], repeating.
 */
export class GpuFftOcean {
  readonly sizes: number[];
  readonly n: number;
  readonly targets: WebGLRenderTarget[];
  /** The pass runner, shared with passes that read the results (foam). */
  readonly fft: GpuInverseFft;
  private readonly spectrumMaterials: RawShaderMaterial[];
  private readonly inputs: DataTexture[] = [];
  private readonly evolved: WebGLRenderTarget;

  /**
   * `filtered`: the result targets are LINEAR-filtered (the caller has checked that float
   * textures are filterable, OES_texture_float_linear), for the ocean's per-pixel reads.
   */
  constructor(
    renderer: WebGLRenderer,
    setup: FftOceanSetup,
    readonly filtered = false,
  ) {
    const n = setup.sea.fftSize;
    this.n = n;
    this.fft = new GpuInverseFft(renderer, n);
    this.sizes = setup.cascades.map((c) => c.size);
    this.evolved = this.fft.createTarget();
    this.targets = setup.tiles.map(() => this.fft.createTarget(filtered));
    this.spectrumMaterials = setup.tiles.map((tile) => {
      const { h0, cycles } = spectrumTextures(tile);
      this.inputs.push(h0, cycles);
      return new RawShaderMaterial({
        name: 'FftSpectrum',
        glslVersion: GLSL3,
        vertexShader: quadVertex,
        fragmentShader: spectrumFragment,
        uniforms: {
          uH0: { value: h0 },
          uCycles: { value: cycles },
          uTauOverT: { value: new Vector3() },
          uTileSize: { value: tile.cascade.size },
          uChoppiness: { value: setup.sea.choppiness },
          uN: { value: n },
        },
        depthTest: false,
        depthWrite: false,
      });
    });
  }

  get displacement(): Texture[] {
    return this.targets.map((t) => t.textures[0]);
  }

  get derivatives(): Texture[] {
    return this.targets.map((t) => t.textures[1]);
  }

  /** Evolves every cascade (or only cascade `only`) to time t (s) and transforms it. t is reduced mod T in float64 here. */
  update(time: number, only?: number): void {
    const [x, y, z] = splitFraction(timeInPeriod(time, REPEAT_PERIOD) / REPEAT_PERIOD);
    this.spectrumMaterials.forEach((material, c) => {
      if (only !== undefined && c !== only) return;
      (material.uniforms.uTauOverT.value as Vector3).set(x, y, z);
      this.fft.draw(material, this.evolved);
      this.fft.transform(this.evolved.textures[0], this.evolved.textures[1], this.targets[c]);
    });
  }

  dispose(): void {
    this.fft.dispose();
    this.evolved.dispose();
    for (const t of this.targets) t.dispose();
    for (const m of this.spectrumMaterials) m.dispose();
    for (const t of this.inputs) t.dispose();
  }
}
