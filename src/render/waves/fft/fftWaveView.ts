import { Vector2, Vector3, type IUniform, type Texture, type WebGLRenderer } from 'three';
import fftChunk from '../../../../shaders/waves/fft.glsl?raw';
import type { OceanParams } from '../../../sim/params/params';
import type { FftWaveModel } from '../../../sim/waves/fft/fftWaveModel';
import { cascadeSpread } from '../../../sim/waves/spectra/spectralBounds';
import { foamJacobianThreshold, foamRemaining, foamThresholdForSpread, JACOBIAN_SPREAD } from '../../../sim/waves/fft/whitecaps';
import { seaSlopeVariance } from '../../../sim/optics/coxMunk';
import { cascadeWavelengths } from '../../../sim/optics/resolvedSlopes';
import { tileOriginTexels } from '../../../sim/waves/originPhases';
import { FftFoam } from './fftFoam';
import { GpuFftOcean } from './gpuFft';
import { WorkerFieldSource } from './fftFieldsSource';
import type { HeightmapLayout, WaveModelView } from '../waveModelView';
import type { PassTiming } from '../../diagnostics/passTiming';

/** Steps longer than this (a seek, a paused jump) rebuild the foam from a short warm-up instead. */
const FOAM_MAX_STEP = 0.25;
/** The warm-up: foam at t is built from the sea at t − 3 s, t − 2.4 s, …, t, so a frozen t always draws the same foam. */
const FOAM_WARMUP_STEPS = 5;
const FOAM_WARMUP_DT = 0.6;
/**
 * Half-width of the foam's soft edge around a Jacobian threshold, as a share of J's spread:
 * foam goes from none to full over ±¼σ, a crisp edge that the texels still resolve.
 */
const FOAM_EDGE = 0.25;
/**
 * Share of Monahan's coverage each remembering cascade starts as fresh foam: the rest of the
 * white is the whole sea's folds now and the foam left behind while it fades.
 */
const CASCADE_FOAM_SHARE = 1 / 3;
/** Step of the fabricated-neighbour normal in the comparison view, m (the finest LOD band's grid step). */
const FABRICATED_DELTA = 1;

type FftUniforms = Record<
  | 'uFftDisplacement0' | 'uFftDisplacement1' | 'uFftDisplacement2'
  | 'uFftDerivatives0' | 'uFftDerivatives1' | 'uFftDerivatives2'
  | 'uFftFoam0' | 'uFftFoam1' | 'uFftFoam2'
  | 'uFftScale' | 'uFftNearOffset' | 'uFftN' | 'uFoamEnabled' | 'uFoamThreshold' | 'uFoamSoftness' | 'uFabricatedDelta'
  | 'uFftSlopeVariance' | 'uFftShortestWave' | 'uFftLongestWave' | 'uSeaSlopeVariance',
  IUniform
>;

/**
 * The spectral sea on the GPU (shaders/waves/fft.glsl): per frame, update(t) evolves every
 * cascade's h₀ to t and runs its inverse FFTs (src/render/waves/fft/gpuFft.ts), then one foam step;
 * the chunk reads the resulting displacement, slope and foam textures. Its CPU twin is
 * `model` (FftWaveModel), fed by a Worker while the clock plays.
 */
export class FftWaveView implements WaveModelView {
  readonly name = 'fft';
  readonly chunkName = 'oceano_waves_fft';
  readonly chunk: string;
  readonly uniforms: FftUniforms;
  private gpu: GpuFftOcean;
  private foam: FftFoam;
  /** Whether the result textures are LINEAR and the chunk reads them filtered per pixel. */
  private readonly filtered: boolean;
  private time = Number.NaN;
  private origin: [number, number] = [0, 0];
  private foamEnabled = true;
  private foamThreshold = 0.7;
  /** Per cascade: its Jacobian threshold and soft edge (each band folds less often than the sea). */
  private cascadeThresholds: number[] = [];
  private cascadeSoftness: number[] = [];
  /** The heightmap view's grey scale: each shown cascade's height at 3σ is white. */
  heightmapLayout: HeightmapLayout = { channel: 1, range: [1, 1] };

  constructor(
    readonly model: FftWaveModel,
    private readonly renderer: WebGLRenderer,
  ) {
    // Float textures filterable: the ocean's pixels read normals and foam through the texture
    // unit's bilinear filter (see shaders/waves/fft.glsl); otherwise by hand, as the vertices.
    this.filtered = renderer.extensions.has('OES_texture_float_linear');
    this.chunk = (this.filtered ? '#define FFT_FILTERED_FIELDS\n' : '') + fftChunk;
    this.uniforms = {
      uFftDisplacement0: { value: null },
      uFftDisplacement1: { value: null },
      uFftDisplacement2: { value: null },
      uFftDerivatives0: { value: null },
      uFftDerivatives1: { value: null },
      uFftDerivatives2: { value: null },
      uFftFoam0: { value: null },
      uFftFoam1: { value: null },
      uFftFoam2: { value: null },
      uFftScale: { value: new Vector3() },
      uFftNearOffset: { value: [new Vector2(), new Vector2(), new Vector2()] },
      uFftN: { value: 1 },
      uFoamEnabled: { value: 1 },
      uFoamThreshold: { value: this.foamThreshold },
      uFoamSoftness: { value: 0.03 },
      uFabricatedDelta: { value: FABRICATED_DELTA },
      uFftSlopeVariance: { value: new Vector3() },
      uFftShortestWave: { value: new Vector3(1, 1, 1) },
      uFftLongestWave: { value: new Vector3(2, 2, 2) },
      uSeaSlopeVariance: { value: 0 },
    };
    this.gpu = new GpuFftOcean(renderer, model.ocean.setup, this.filtered);
    this.foam = new FftFoam(this.gpu);
    this.bindTextures();
    model.attachSource(
      new WorkerFieldSource(
        (sea, time, fields) => model.receive(sea, time, fields),
        (ms) => model.addMainThreadMs(ms),
      ),
    );
  }

  /**
   * The heightmap teaching view under waves=fft: the largest cascade's height field (the swell
   * of the spectral peak, one tile of 8 peak wavelengths) beside the smallest's (the short
   * waves), as the GPU FFT wrote them this frame.
   */
  get heightmapTextures(): [Texture, Texture] {
    const displacement = this.gpu.displacement;
    return [displacement[0], displacement[displacement.length - 1]];
  }

  /** waveLensHeight reads the smallest cascade alone, so it repeats with that tile. */
  get lensPeriod(): number {
    return this.model.ocean.setup.cascades[2].size;
  }

  private bindTextures(): void {
    const setup = this.model.ocean.setup;
    if (setup.cascades.length !== 3) throw new RangeError(`shaders/waves/fft.glsl reads 3 cascades, the sea has ${setup.cascades.length}.`);
    const u = this.uniforms;
    const n = setup.sea.fftSize;
    this.gpu.displacement.forEach((t, c) => (u[`uFftDisplacement${c}` as 'uFftDisplacement0'].value = t));
    this.gpu.derivatives.forEach((t, c) => (u[`uFftDerivatives${c}` as 'uFftDerivatives0'].value = t));
    (u.uFftScale.value as Vector3).set(n / setup.cascades[0].size, n / setup.cascades[1].size, n / setup.cascades[2].size);
    u.uFftN.value = n;
    this.placeNearOffsets();
    this.bindFoam();
  }

  /** The render origin the pixels' relative grid points are measured from (OceanMaterial.onBeforeRender). */
  setRenderOrigin(x: number, z: number): void {
    if (x === this.origin[0] && z === this.origin[1]) return;
    this.origin = [x, z];
    this.placeNearOffsets();
  }

  /** Where the render origin falls in each cascade's tile, in texels (src/sim/waves/originPhases.ts). */
  private placeNearOffsets(): void {
    const { sea, cascades } = this.model.ocean.setup;
    const offsets = this.uniforms.uFftNearOffset.value as Vector2[];
    cascades.forEach((cascade, c) => offsets[c].fromArray(tileOriginTexels(cascade.size, sea.fftSize, this.origin[0], this.origin[1])));
  }

  private bindFoam(): void {
    this.foam.textures.forEach((t, c) => (this.uniforms[`uFftFoam${c}` as 'uFftFoam0'].value = t));
  }

  setParams(params: OceanParams): void {
    // Foam switched on starts from the warm-up (the picture of a frozen t does not depend on
    // whether foam was off before), see update.
    const foamToggled = params.foam !== this.foamEnabled;
    this.foamEnabled = params.foam;
    this.foamThreshold = foamJacobianThreshold(params.windSpeed, params.choppiness, params.foamThreshold);
    this.uniforms.uFoamEnabled.value = params.foam ? 1 : 0;
    this.uniforms.uFoamThreshold.value = this.foamThreshold;
    this.uniforms.uFoamSoftness.value = FOAM_EDGE * JACOBIAN_SPREAD * params.choppiness;
    const rebuilt = this.model.setParams(params);
    const { sea, tiles } = this.model.ocean.setup;
    const cascadeSpreads = tiles.map((tile) => cascadeSpread(tile, sea.depth));
    const spreads = cascadeSpreads.map((spread) => sea.choppiness * spread.slope);
    this.setSlopeStatistics(cascadeSpreads.map((spread) => spread.slope * spread.slope), params.windSpeed);
    this.heightmapLayout = { channel: 1, range: [3 * cascadeSpreads[0].height, 3 * cascadeSpreads[cascadeSpreads.length - 1].height] };
    const thresholds = spreads.map((spread) => foamThresholdForSpread(spread, params.windSpeed, params.foamThreshold, CASCADE_FOAM_SHARE));
    const changed = thresholds.some((t, c) => t !== this.cascadeThresholds[c]);
    this.cascadeThresholds = thresholds;
    this.cascadeSoftness = spreads.map((spread) => FOAM_EDGE * spread);
    if (rebuilt) {
      this.foam.dispose();
      this.gpu.dispose();
      this.gpu = new GpuFftOcean(this.renderer, this.model.ocean.setup, this.filtered);
      this.foam = new FftFoam(this.gpu);
      this.bindTextures();
    }
    // New thresholds make other foam: rebuild it from the warm-up at the next update.
    if (rebuilt || changed || foamToggled) this.time = Number.NaN;
  }

  /**
   * What the glint needs to turn the slopes a pixel cannot show into roughness (shaders/waves/fft.glsl):
   * each cascade's realised mean-square slope and band of wavelengths, and Cox & Munk's total.
   */
  private setSlopeStatistics(cascadeVariances: number[], windSpeed: number): void {
    const { sea, cascades } = this.model.ocean.setup;
    const bands = cascades.map((cascade) => cascadeWavelengths(cascade, sea.fftSize));
    (this.uniforms.uFftSlopeVariance.value as Vector3).fromArray(cascadeVariances);
    (this.uniforms.uFftShortestWave.value as Vector3).fromArray(bands.map((band) => band.shortest));
    (this.uniforms.uFftLongestWave.value as Vector3).fromArray(bands.map((band) => band.longest));
    this.uniforms.uSeaSlopeVariance.value = seaSlopeVariance(windSpeed);
  }

  /** FFT passes for every cascade at `time`, then the foam (stepped, or rebuilt after a jump). */
  update(time: number): void {
    if (Object.is(time, this.time)) return;
    const previous = this.time;
    this.time = time;
    this.model.prefetch(time);
    if (!this.foamEnabled) {
      // The foam pass runs anyway, fresh (decay 0): its texture also carries ∂Dx/∂x for the
      // ocean's pixels (shaders/fftFoam.frag); uFoamEnabled hides the foam itself.
      this.gpu.update(time);
      this.foam.step(0, this.cascadeThresholds, this.cascadeSoftness);
      this.bindFoam();
      return;
    }
    const dt = time - previous;
    if (dt > 0 && dt <= FOAM_MAX_STEP) {
      this.gpu.update(time);
      this.foam.step(foamRemaining(dt), this.cascadeThresholds, this.cascadeSoftness);
    } else {
      for (let k = FOAM_WARMUP_STEPS; k >= 0; k--) {
        this.gpu.update(time - k * FOAM_WARMUP_DT);
        this.foam.step(k === FOAM_WARMUP_STEPS ? 0 : foamRemaining(FOAM_WARMUP_DT), this.cascadeThresholds, this.cascadeSoftness);
      }
    }
    this.bindFoam();
  }

  /**
   * The FFT passes of every cascade at the current time again (same spectrum, same time: same
   * textures), then one foam step with no fade (max(old, fresh) with fresh already in old:
   * the foam is unchanged), each group timed between two GPU syncs.
   */
  profilePasses(sync: () => void): PassTiming[] {
    if (Number.isNaN(this.time)) return [];
    sync();
    let start = performance.now();
    this.gpu.update(this.time);
    sync();
    const timings: PassTiming[] = [{ name: 'fft', ms: performance.now() - start }];
    start = performance.now();
    // Foam off, the pass still runs fresh (it carries ∂Dx/∂x for the pixels, see update).
    this.foam.step(this.foamEnabled ? 1 : 0, this.cascadeThresholds, this.cascadeSoftness);
    sync();
    this.bindFoam();
    timings.push({ name: 'foam', ms: performance.now() - start });
    return timings;
  }

  /** The fields and the foam lived in render targets: the next update runs the FFTs and the foam's warm-up again. */
  contextRestored(): void {
    this.time = Number.NaN;
  }

  dispose(): void {
    this.model.dispose();
    this.foam.dispose();
    this.gpu.dispose();
  }
}
