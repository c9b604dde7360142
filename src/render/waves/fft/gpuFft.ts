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
 * Two RGBA32F colour attachments of width × height, written together by every pass (MRT). Needs EXT_color_buffer_float.
 * `filtered`: LINEAR, for the ocean's pixels' filtered reads (shaders/waves/fft.glsl); texelFetch ignores it.
 */
function mrtTarget(width: number, height: number, filtered = false): WebGLRenderTarget {
  const filter = filtered ? LinearFilter : NearestFilter;
  return new WebGLRenderTarget(width, height, {
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

/** Which tiles of an atlas a pass covers: `count` tiles from `first`. */
export interface TileRange {
  first: number;
  count: number;
}

/** Where one tile of the atlas lands after the transform: its own n × n target. */
export interface TileOutput {
  tile: number;
  target: WebGLRenderTarget;
}

/**
 * GPU inverse 2-D FFTs of n × n grids, four complex signals at a time (two RGBA32F textures),
 * by Stockham passes: per axis the stages of stockhamRadices(n) (src/sim/waves/fft/stockhamFft.ts,
 * its CPU mirror), radix 4 where it fits and one radix-2 stage for odd log₂n: 8 passes for 128²
 * instead of 14 radix-2 passes.
 *
 * Several grids go through the same passes: they lie side by side along x as the tiles of one
 * atlas (tiles·n × n), and each stage is one draw over all of them (shaders/fftStage.frag keeps
 * each stage inside its tile). A pass costs a render-target switch and a draw whatever its size,
 * so three cascades in one atlas take the passes of one. The stages ping-pong between two atlas
 * targets; the last stage writes each tile straight into its own n × n target (one draw per
 * tile: WebGL2 promises only 4 colour attachments, and a tile has 2), which the ocean samples
 * with wrapping and filtering, as a tile of an atlas could not be.
 */
export class GpuInverseFft {
  readonly n: number;
  readonly tiles: number;
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly mesh: Mesh;
  /** The stage material of each radix (shaders/fftStage.frag, RADIX_4 for 4): compiled apart rather than branched on (perf: see setMaterialDefine). */
  private readonly stages: Map<number, RawShaderMaterial>;
  private readonly radices: number[];
  private readonly twiddle: DataTexture;
  /** The two atlases the stages ping-pong between; the first is also `workspace`. */
  private readonly atlases: [WebGLRenderTarget, WebGLRenderTarget];

  /** `tiles`: grids per atlas; `radices`: the stages per axis, stockhamRadices(n) unless a test asks for others (all 2: the radix-2 passes). */
  constructor(renderer: WebGLRenderer, n: number, tiles = 1, radices?: readonly number[]) {
    if (!renderer.extensions.has('EXT_color_buffer_float'))
      throw new Error('The spectral ocean needs WebGL2 float render targets (EXT_color_buffer_float).');
    this.renderer = renderer;
    this.n = n;
    this.tiles = tiles;
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
          uTileOrigin: { value: 0 },
        },
        depthTest: false,
        depthWrite: false,
      });
    this.stages = new Map([...new Set(this.radices)].map((radix) => [radix, stage(radix)]));
    this.mesh = new Mesh(geometry, this.stages.get(this.radices[0]));
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
    this.atlases = [mrtTarget(tiles * n, n), mrtTarget(tiles * n, n)];
  }

  /** A render target for one tile's result (LINEAR-filtered when `filtered`). */
  createTarget(filtered = false): WebGLRenderTarget {
    return mrtTarget(this.n, this.n, filtered);
  }

  /** An atlas the caller may draw its spectra into and hand to transform (the stages then ping-pong around it). */
  get workspace(): WebGLRenderTarget {
    return this.atlases[0];
  }

  /**
   * Draws `material` over every texel of `target` (any size), or only over the tiles `range`
   * of an atlas (the viewport: gl_FragCoord stays in atlas texels). Leaves the renderer's own target as it was.
   */
  draw(material: RawShaderMaterial, target: WebGLRenderTarget, range?: TileRange): void {
    const previous = this.renderer.getRenderTarget();
    const autoClear = this.renderer.autoClear;
    this.renderer.autoClear = false;
    this.mesh.material = material;
    if (range) target.viewport.set(range.first * this.n, 0, range.count * this.n, this.n);
    this.renderer.setRenderTarget(target);
    this.renderer.render(this.scene, this.camera);
    target.viewport.set(0, 0, target.width, target.height);
    this.renderer.setRenderTarget(previous);
    this.renderer.autoClear = autoClear;
  }

  /** Reads an n × n float target back into `rgba` (4 n² values), for diagnostics. */
  read(target: WebGLRenderTarget, rgba: Float32Array): void {
    this.renderer.readRenderTargetPixels(target, 0, 0, this.n, this.n, rgba);
  }

  /**
   * Inverse-transforms the atlas in the two textures (rows, then columns), the tiles of `range`
   * (default: all), and writes each tile named in `outputs` into its target.
   */
  transform(input0: Texture, input1: Texture, outputs: readonly TileOutput[], range: TileRange = { first: 0, count: this.tiles }): void {
    const steps = [false, true].flatMap((vertical) => {
      let halfSize = 1;
      return this.radices.map((radix) => {
        const step = { radix, vertical, halfSize };
        halfSize *= radix;
        return step;
      });
    });
    let source: [Texture, Texture] = [input0, input1];
    // Never write the atlas being read: start on the one that is not the input.
    let write = input0 === this.atlases[1].textures[0] ? 0 : 1;
    steps.forEach(({ radix, vertical, halfSize }, s) => {
      const stage = this.stages.get(radix) as RawShaderMaterial;
      const u = stage.uniforms;
      u.uInput0.value = source[0];
      u.uInput1.value = source[1];
      u.uHalfSize.value = halfSize;
      u.uVertical.value = vertical;
      if (s < steps.length - 1) {
        u.uTileOrigin.value = 0;
        this.draw(stage, this.atlases[write], range);
        source = [this.atlases[write].textures[0], this.atlases[write].textures[1]];
        write = 1 - write;
        return;
      }
      for (const { tile, target } of outputs) {
        u.uTileOrigin.value = tile * this.n;
        this.draw(stage, target);
      }
    });
  }

  dispose(): void {
    for (const stage of this.stages.values()) stage.dispose();
    this.twiddle.dispose();
    for (const atlas of this.atlases) atlas.dispose();
    this.mesh.geometry.dispose();
  }
}

/**
 * Every cascade's h₀(k) and h₀(−k) side by side, and ω as whole cycles m per repeat period (split as in
 * fftSpectrum.frag: 4096·mh, ml, m), as two float32 atlases of the cascades' n × n tiles along x: one upload each.
 */
function spectrumAtlases(tiles: readonly SpectralTile[]): { h0: DataTexture; cycles: DataTexture } {
  const n = tiles[0].n;
  const width = tiles.length * n;
  const pairs = new Float32Array(4 * width * n);
  const cycles = new Float32Array(4 * width * n);
  const omega0 = (2 * Math.PI) / REPEAT_PERIOD;
  tiles.forEach((tile, c) => {
    for (let b = 0; b < n; b++) {
      for (let a = 0; a < n; a++) {
        const i = b * n + a;
        const j = ((n - b) % n) * n + ((n - a) % n);
        const texel = 4 * (b * width + c * n + a);
        pairs[texel] = tile.h0[2 * i];
        pairs[texel + 1] = tile.h0[2 * i + 1];
        pairs[texel + 2] = tile.h0[2 * j];
        pairs[texel + 3] = tile.h0[2 * j + 1];
        const m = Math.round(tile.omega[i] / omega0);
        if (m >= 2 ** 24) throw new Error('A wave too fast for the float32 phase split (m ≥ 2²⁴).');
        const low = m % 4096;
        cycles[texel] = m - low;
        cycles[texel + 1] = low;
        cycles[texel + 2] = m;
      }
    }
  });
  return {
    h0: floatTexture(pairs, width, n, RGBAFormat, RepeatWrapping),
    cycles: floatTexture(cycles, width, n, RGBAFormat, RepeatWrapping),
  };
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
 * The spectral ocean on the GPU. h₀ of every cascade is uploaded once (drawn on the CPU from the
 * seed, the same numbers as the CPU twin) as one atlas; each update(t) is then one time-evolution
 * pass over the atlas and the FFT passes of GpuInverseFft (2·⌈log₂n / 2⌉ stages, radix 4, the last
 * one drawn once per tile): 1 + 7 + 3 = 11 passes for three cascades of 128², instead of
 * 3 × 9 with a set of passes per cascade. After update, per cascade c:
 *   displacement[c]: RGBA32F n × n, (dx, dy, dz, ∂Dx/∂x)
 *   derivatives[c]:  RGBA32F n × n, (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
 * Texel (p, q) is the grid point x = p·L/n, z = q·L/n of a tile of side L = sizes[c], repeating.
 *
 * With `latticeCascade`, the atlas has one tile more: that cascade again, at a time of its own
 * (the foam's lattice time, src/sim/waves/fft/foamMemory.ts), transformed in the same passes
 * when a frame needs both, and landing in `lattice`.
 */
export class GpuFftOcean {
  readonly sizes: number[];
  readonly n: number;
  readonly targets: WebGLRenderTarget[];
  /** The lattice tile's result (the same two textures as a cascade's), or null without one. */
  readonly lattice: WebGLRenderTarget | null;
  /** The pass runner, shared with passes that read the results (foam). */
  readonly fft: GpuInverseFft;
  private readonly spectrum: RawShaderMaterial;
  private readonly inputs: DataTexture[];
  private readonly cascades: number;

  /**
   * `filtered`: the result targets are LINEAR-filtered (the caller has checked that float
   * textures are filterable, OES_texture_float_linear), for the ocean's per-pixel reads.
   */
  constructor(
    renderer: WebGLRenderer,
    setup: FftOceanSetup,
    readonly filtered = false,
    latticeCascade?: number,
  ) {
    const n = setup.sea.fftSize;
    this.n = n;
    this.cascades = setup.tiles.length;
    // Atlas tile → the cascade it evolves: each cascade in its own tile, then the lattice tile.
    const cascadeOf = setup.tiles.map((_, c) => c);
    if (latticeCascade !== undefined) cascadeOf.push(latticeCascade);
    this.fft = new GpuInverseFft(renderer, n, cascadeOf.length);
    this.sizes = setup.cascades.map((c) => c.size);
    this.targets = setup.tiles.map(() => this.fft.createTarget(filtered));
    this.lattice = latticeCascade === undefined ? null : this.fft.createTarget();
    const { h0, cycles } = spectrumAtlases(setup.tiles);
    this.inputs = [h0, cycles];
    this.spectrum = new RawShaderMaterial({
      name: 'FftSpectrum',
      glslVersion: GLSL3,
      vertexShader: quadVertex,
      fragmentShader: spectrumFragment,
      defines: { TILES: cascadeOf.length },
      uniforms: {
        uH0: { value: h0 },
        uCycles: { value: cycles },
        uCascade: { value: cascadeOf },
        uTauOverT: { value: cascadeOf.map(() => new Vector3()) },
        uTileSize: { value: cascadeOf.map((c) => setup.cascades[c].size) },
        uChoppiness: { value: setup.sea.choppiness },
        uN: { value: n },
      },
      depthTest: false,
      depthWrite: false,
    });
  }

  get displacement(): Texture[] {
    return this.targets.map((t) => t.textures[0]);
  }

  get derivatives(): Texture[] {
    return this.targets.map((t) => t.textures[1]);
  }

  /**
   * Evolves every cascade to time t (s) and transforms them; with `latticeTime`, the lattice tile
   * too, in the same passes. Times are reduced mod T in float64 here.
   */
  update(time: number, latticeTime?: number): void {
    const range = { first: 0, count: this.cascades + (latticeTime === undefined ? 0 : 1) };
    for (let tile = 0; tile < this.cascades; tile++) this.setTime(tile, time);
    if (latticeTime !== undefined) this.setTime(this.cascades, latticeTime);
    this.run(range);
  }

  /** Evolves and transforms the lattice tile alone (its tile of the atlas: a pass over a third of the texels). */
  updateLattice(latticeTime: number): void {
    if (!this.lattice) throw new Error('This ocean was built without a lattice tile.');
    this.setTime(this.cascades, latticeTime);
    this.run({ first: this.cascades, count: 1 });
  }

  private setTime(tile: number, time: number): void {
    const [x, y, z] = splitFraction(timeInPeriod(time, REPEAT_PERIOD) / REPEAT_PERIOD);
    (this.spectrum.uniforms.uTauOverT.value as Vector3[])[tile].set(x, y, z);
  }

  private run(range: TileRange): void {
    const workspace = this.fft.workspace;
    this.fft.draw(this.spectrum, workspace, range);
    const outputs: TileOutput[] = this.targets.map((target, tile) => ({ tile, target }));
    if (this.lattice) outputs.push({ tile: this.cascades, target: this.lattice });
    const inRange = outputs.filter(({ tile }) => tile >= range.first && tile < range.first + range.count);
    this.fft.transform(workspace.textures[0], workspace.textures[1], inRange, range);
  }

  dispose(): void {
    this.fft.dispose();
    for (const t of this.targets) t.dispose();
    this.lattice?.dispose();
    this.spectrum.dispose();
    for (const t of this.inputs) t.dispose();
  }
}
