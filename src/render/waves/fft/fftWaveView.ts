import { Vector2, Vector3, Vector4, type IUniform, type Texture, type WebGLRenderer } from 'three';
import fftChunk from '../../../../shaders/waves/fft.glsl?raw';
import breakingChunk from '../../../../shaders/waves/fftBreaking.glsl?raw';
import breakupChunk from '../../../../shaders/foam/foamBreakup.glsl?raw';
import windrowsChunk from '../../../../shaders/foam/foamWindrows.glsl?raw';
import type { OceanParams } from '../../../sim/params/params';
import type { FftWaveModel } from '../../../sim/waves/fft/fftWaveModel';
import { cascadeSpread } from '../../../sim/waves/spectra/spectralBounds';
import { foamRemaining, whitecapCoverage } from '../../../sim/waves/fft/whitecaps';
import { breakingSpread, breakingThreshold, jacobianCovariance } from '../../../sim/waves/fft/breaking';
import { WINDROW_STREAM, windrowLattice, windrowStrength } from '../../../sim/waves/fft/windrows';
import {
  BREAKUP_STREAM,
  BREAKUP_STRENGTH,
  breakupLattice,
  breakupNoise,
  foamBreakup,
  type FoamBreakup,
} from '../../../sim/waves/fft/foamBreakup';
import { FOAM_STEP_SECONDS, foamSteps } from '../../../sim/waves/fft/foamMemory';
import { foamDriftStep, foamDriftVelocity } from '../../../sim/waves/fft/foamDrift';
import { seededRandom } from '../../../sim/noise/integerHash';
import { seaSlopeVariance } from '../../../sim/optics/coxMunk';
import { cascadeWavelengths } from '../../../sim/optics/resolvedSlopes';
import { tileOriginTexels } from '../../../sim/waves/originPhases';
import { FftFoam, REMEMBERING_CASCADE } from './fftFoam';
import { GpuFftOcean } from './gpuFft';
import { WorkerFieldSource } from './fftFieldsSource';
import type { HeightmapLayout, WaveModelView } from '../waveModelView';
import type { PassTiming } from '../../diagnostics/passTiming';

/**
 * Half-width of the foam's soft edge around a breaking threshold, as a share of the breaking
 * measure's spread: foam goes from none to full over ±¼σ, a crisp edge that the texels still resolve.
 */
const FOAM_EDGE = 0.25;
/**
 * Share of Monahan's coverage that breaks now, on the whole sea (the active layer); the rest
 * of the white is the foam left behind while it fades (the remembered layer).
 */
const ACTIVE_FOAM_SHARE = 0.9;
/**
 * The same without wave groups (the waveGroups parameter off, for the lesson). The breaking
 * measure is then narrower, so more of what breaks lies in the soft edge's lace, which does
 * not read as white: this share keeps the white seen from above Monahan's (measured on the
 * rendered frame, tests/browser/light/foam.test.ts).
 */
const ACTIVE_FOAM_SHARE_WITHOUT_GROUPS = 1.12;
/** Share of Monahan's coverage the remembering cascade marks as fresh foam at each lattice time, against its own band's statistics. */
const REMEMBERED_FOAM_SHARE = 1 / 6;
/** Step of the fabricated-neighbour normal in the comparison view, m (the finest LOD band's grid step). */
const FABRICATED_DELTA = 1;

type FftUniforms = Record<
  | 'uFftDisplacement0'
  | 'uFftDisplacement1'
  | 'uFftDisplacement2'
  | 'uFftDerivatives0'
  | 'uFftDerivatives1'
  | 'uFftDerivatives2'
  | 'uFftFoam0'
  | 'uFftFoam1'
  | 'uFftFoam2'
  | 'uFftScale'
  | 'uFftNearOffset'
  | 'uFftN'
  | 'uFoamEnabled'
  | 'uFoamThreshold'
  | 'uFoamSoftness'
  | 'uFabricatedDelta'
  | 'uFftSlopeVariance'
  | 'uFftLogLongestWave'
  | 'uFftPerLogBand'
  | 'uSeaSlopeVariance'
  | 'uFoamBreakupScale'
  | 'uFoamBreakupCells'
  | 'uFoamBreakupOffset'
  | 'uFoamBreakupOrigin'
  | 'uFoamBreakupSeed'
  | 'uFoamBreakupStrength'
  | 'uWindrowAxes'
  | 'uWindrowCells'
  | 'uWindrowOffset'
  | 'uWindrowSeed'
  | 'uWindrowStrength',
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
  /** e-folding time of the remembered foam, s. */
  private foamFade = 2.5;
  /** The remembering cascade's breaking threshold (bias included) and the unit of its potential. */
  private memoryThreshold = 0;
  private memorySoftness = 1;
  /** The last lattice index the memory was stepped to; null: start from nothing at the next update. */
  private foamDone: number | null = null;
  /** Thresholds before the user's bias, from the sea's statistics: recomputed only when the sea is rebuilt. */
  private baseThresholds: { active: number; activeSoftness: number; memory: number; memorySoftness: number } | null = null;
  private breakup: FoamBreakup;
  /** Whether the whitecaps break in groups (the waveGroups parameter): the threshold counts the field's shift. */
  private groups = true;
  /** The surface drift that carries the remembered foam, m/s (x, z); zero for the drift's negative control. */
  private foamDrift: [number, number] = [0, 0];
  private foamDrifts = true;
  /** The heightmap view's grey scale: each shown cascade's height at 3σ is white. */
  heightmapLayout: HeightmapLayout = { channel: 1, range: [1, 1] };

  constructor(
    readonly model: FftWaveModel,
    private readonly renderer: WebGLRenderer,
  ) {
    // Float textures filterable: the ocean's pixels read normals and foam through the texture
    // unit's bilinear filter (see shaders/waves/fft.glsl); otherwise by hand, as the vertices.
    this.filtered = renderer.extensions.has('OES_texture_float_linear');
    this.chunk = (this.filtered ? '#define FFT_FILTERED_FIELDS\n' : '') + [breakingChunk, breakupChunk, windrowsChunk, fftChunk].join('\n');
    this.breakup = foamBreakup(model.ocean.setup.sea);
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
      uFoamThreshold: { value: 0.7 },
      uFoamSoftness: { value: 0.03 },
      uFoamBreakupScale: { value: 1 },
      uFoamBreakupCells: { value: new Vector4() },
      uFoamBreakupOffset: { value: new Vector4() },
      uFoamBreakupOrigin: { value: new Vector2() },
      uFoamBreakupSeed: { value: 0 },
      uFoamBreakupStrength: { value: 0 },
      uWindrowAxes: { value: new Vector4() },
      uWindrowCells: { value: new Vector2() },
      uWindrowOffset: { value: new Vector2() },
      uWindrowSeed: { value: 0 },
      uWindrowStrength: { value: 0 },
      uFabricatedDelta: { value: FABRICATED_DELTA },
      uFftSlopeVariance: { value: new Vector3() },
      uFftLogLongestWave: { value: new Vector3(Math.LN2, Math.LN2, Math.LN2) },
      uFftPerLogBand: { value: new Vector3(1 / Math.LN2, 1 / Math.LN2, 1 / Math.LN2) },
      uSeaSlopeVariance: { value: 0 },
    };
    this.gpu = new GpuFftOcean(renderer, model.ocean.setup, this.filtered, REMEMBERING_CASCADE);
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
    this.placeFoamLattices();
  }

  /** Where the render origin falls on the foam's drifting lattices at this time: the breakup field's and the windrows'. */
  private placeFoamLattices(): void {
    const time = Number.isNaN(this.time) ? 0 : this.time;
    const lattice = breakupLattice(this.breakup, this.origin[0], this.origin[1], time);
    (this.uniforms.uFoamBreakupCells.value as Vector4).fromArray(lattice.cells);
    (this.uniforms.uFoamBreakupOffset.value as Vector4).fromArray(lattice.offset);
    (this.uniforms.uFoamBreakupOrigin.value as Vector2).fromArray(this.origin);
    const rows = windrowLattice(this.model.ocean.setup.sea, this.origin[0], this.origin[1], time);
    (this.uniforms.uWindrowAxes.value as Vector4).fromArray(rows.axes);
    (this.uniforms.uWindrowCells.value as Vector2).fromArray(rows.cells);
    (this.uniforms.uWindrowOffset.value as Vector2).fromArray(rows.offset);
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
    // Foam switched on starts from nothing at the next update (the picture of a frozen t does
    // not depend on whether foam was off before), see update.
    const foamToggled = params.foam !== this.foamEnabled;
    const fadeChanged = params.foamFade !== this.foamFade;
    this.foamEnabled = params.foam;
    this.foamFade = params.foamFade;
    this.uniforms.uFoamEnabled.value = params.foam ? 1 : 0;
    const rebuilt = this.model.setParams(params);
    const { sea, tiles } = this.model.ocean.setup;
    const cascadeSpreads = tiles.map((tile) => cascadeSpread(tile, sea.depth));
    this.setSlopeStatistics(
      cascadeSpreads.map((spread) => spread.slope * spread.slope),
      params.windSpeed,
    );
    this.heightmapLayout = { channel: 1, range: [3 * cascadeSpreads[0].height, 3 * cascadeSpreads[cascadeSpreads.length - 1].height] };
    const groupsToggled = params.waveGroups !== this.groups;
    this.groups = params.waveGroups;
    if (rebuilt || !this.baseThresholds || groupsToggled) {
      this.breakup = foamBreakup(sea);
      this.baseThresholds = this.foamThresholds();
      this.uniforms.uFoamBreakupScale.value = 1 / this.breakup.cell;
      this.uniforms.uFoamBreakupSeed.value = (sea.seed ^ BREAKUP_STREAM) | 0;
      this.uniforms.uWindrowSeed.value = (sea.seed ^ WINDROW_STREAM) | 0;
      this.uniforms.uWindrowStrength.value = windrowStrength(sea.windSpeed);
      this.placeFoamLattices();
    }
    const base = this.baseThresholds;
    const memoryThreshold = base.memory + params.foamThreshold;
    const changed = memoryThreshold !== this.memoryThreshold || base.memorySoftness !== this.memorySoftness;
    this.memoryThreshold = memoryThreshold;
    this.memorySoftness = base.memorySoftness;
    this.uniforms.uFoamThreshold.value = base.active + params.foamThreshold;
    this.uniforms.uFoamSoftness.value = base.activeSoftness;
    if (rebuilt) {
      this.foam.dispose();
      this.gpu.dispose();
      this.gpu = new GpuFftOcean(this.renderer, this.model.ocean.setup, this.filtered, REMEMBERING_CASCADE);
      this.foam = new FftFoam(this.gpu);
      this.bindTextures();
    }
    const driftChanged = this.placeFoamDrift();
    // Other thresholds, another fade or another drift make other foam: rebuilt from nothing at the next update.
    if (rebuilt || changed || foamToggled || fadeChanged || driftChanged) {
      this.foamDone = null;
      this.time = Number.NaN;
    }
  }

  /**
   * The breaking thresholds from the sea's Jacobian statistics (src/sim/waves/fft/breaking.ts):
   * the whole sea's, with the breakup field's shift while the whitecaps break in groups, for the foam breaking now, on
   * ACTIVE_FOAM_SHARE of Monahan's coverage; the remembering cascade's own, for the foam it
   * deposits, on REMEMBERED_FOAM_SHARE of it (one band alone folds less often than the sea).
   */
  private foamThresholds(): { active: number; activeSoftness: number; memory: number; memorySoftness: number } {
    const { sea, tiles } = this.model.ocean.setup;
    const coverage = whitecapCoverage(sea.windSpeed);
    const whole = jacobianCovariance(tiles, sea.choppiness);
    const spread = breakingSpread(whole);
    const strength = BREAKUP_STRENGTH * spread;
    this.uniforms.uFoamBreakupStrength.value = strength;
    const random = seededRandom(0xb7ea);
    const shift = () => strength * breakupNoise(1e4 * random(), 1e4 * random(), sea.seed);
    const own = jacobianCovariance([tiles[REMEMBERING_CASCADE]], sea.choppiness);
    return {
      active: this.groups
        ? breakingThreshold(whole, ACTIVE_FOAM_SHARE * coverage, shift)
        : breakingThreshold(whole, ACTIVE_FOAM_SHARE_WITHOUT_GROUPS * coverage),
      activeSoftness: FOAM_EDGE * spread,
      memory: breakingThreshold(own, REMEMBERED_FOAM_SHARE * coverage),
      memorySoftness: FOAM_EDGE * breakingSpread(own),
    };
  }

  /**
   * What the glint needs to turn the slopes a pixel cannot show into roughness (shaders/waves/fft.glsl):
   * each cascade's realised mean-square slope and band of wavelengths, and Cox & Munk's total.
   */
  private setSlopeStatistics(cascadeVariances: number[], windSpeed: number): void {
    const { sea, cascades } = this.model.ocean.setup;
    const bands = cascades.map((cascade) => cascadeWavelengths(cascade, sea.fftSize));
    (this.uniforms.uFftSlopeVariance.value as Vector3).fromArray(cascadeVariances);
    // The pixels' resolvedShare (src/sim/optics/resolvedSlopes.ts) with its logarithms taken once here.
    (this.uniforms.uFftLogLongestWave.value as Vector3).fromArray(bands.map((band) => Math.log(band.longest)));
    (this.uniforms.uFftPerLogBand.value as Vector3).fromArray(bands.map((band) => 1 / Math.log(band.longest / band.shortest)));
    this.uniforms.uSeaSlopeVariance.value = seaSlopeVariance(windSpeed);
  }

  /**
   * FFT passes for every cascade at `time`, then the foam: the remembered foam's lattice steps up
   * to `time` (src/sim/waves/fft/foamMemory.ts; each needs the remembering cascade at its lattice
   * time, the ocean's lattice tile), then the pack the pixels read. A played frame has at most
   * one lattice step, the last, and its tile rides in the frame's own FFT passes; the steps
   * before it (a jump, a first frame, a slow frame) run the lattice tile alone.
   */
  update(time: number): void {
    if (Object.is(time, this.time)) return;
    this.time = time;
    this.model.prefetch(time);
    this.placeFoamLattices();
    let fade = 0;
    if (this.foamEnabled) {
      const steps = foamSteps(this.foamDone, time, this.foamFade);
      const decay = foamRemaining(FOAM_STEP_SECONDS, this.foamFade);
      const texel = this.memoryTexel();
      for (let k = steps.first; k <= steps.last; k++) {
        if (k < steps.last) this.gpu.updateLattice(k * FOAM_STEP_SECONDS);
        else this.gpu.update(time, k * FOAM_STEP_SECONDS);
        const drift = foamDriftStep(this.foamDrift, texel, k);
        this.foam.remember(k === steps.first && steps.fresh ? 0 : decay, this.memoryThreshold, this.memorySoftness, drift);
      }
      if (steps.first > steps.last) this.gpu.update(time);
      this.foamDone = steps.last;
      fade = steps.fade;
    } else {
      this.foamDone = null;
      this.gpu.update(time);
    }
    this.foam.pack(fade);
    this.bindFoam();
  }

  /** The side of one texel of the remembering cascade's tile, m. */
  private memoryTexel(): number {
    const { sea, cascades } = this.model.ocean.setup;
    return cascades[REMEMBERING_CASCADE].size / sea.fftSize;
  }

  readFoamMemory(): { n: number; texel: number; data: Float32Array } {
    return { n: this.model.ocean.setup.sea.fftSize, texel: this.memoryTexel(), data: this.foam.readMemory() };
  }

  setFoamDrift(on: boolean): void {
    this.foamDrifts = on;
    if (this.placeFoamDrift()) {
      this.foamDone = null;
      this.time = Number.NaN;
    }
  }

  /** The remembered foam's drift for the current sea (none while the control turns it off); whether it changed. */
  private placeFoamDrift(): boolean {
    const drift = this.foamDrifts ? foamDriftVelocity(this.model.ocean.setup.sea) : ([0, 0] as [number, number]);
    const changed = drift[0] !== this.foamDrift[0] || drift[1] !== this.foamDrift[1];
    this.foamDrift = drift;
    return changed;
  }

  /**
   * The FFT passes of every cascade at the current time again (same spectrum, same time: same
   * textures), one lattice step of the remembered foam drawn but not kept, and the pack, each
   * group timed between two GPU syncs.
   */
  profilePasses(sync: () => void): PassTiming[] {
    if (Number.isNaN(this.time)) return [];
    sync();
    let start = performance.now();
    this.gpu.update(this.time);
    sync();
    const timings: PassTiming[] = [{ name: 'fft', ms: performance.now() - start }];
    start = performance.now();
    this.foam.remember(foamRemaining(FOAM_STEP_SECONDS, this.foamFade), this.memoryThreshold, this.memorySoftness, [0, 0], false);
    const fade = this.foamEnabled && this.foamDone !== null ? foamSteps(this.foamDone, this.time, this.foamFade).fade : 0;
    this.foam.pack(fade);
    sync();
    this.bindFoam();
    timings.push({ name: 'foam', ms: performance.now() - start });
    return timings;
  }

  /** The fields and the foam lived in render targets: the next update runs the FFTs and the foam's warm-up again. */
  contextRestored(): void {
    this.time = Number.NaN;
    this.foamDone = null;
  }

  dispose(): void {
    this.model.dispose();
    this.foam.dispose();
    this.gpu.dispose();
  }
}
