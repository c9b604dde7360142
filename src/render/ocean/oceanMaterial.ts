import {
  BackSide,
  Color,
  DoubleSide,
  FrontSide,
  Matrix4,
  NoToneMapping,
  ShaderMaterial,
  Vector2,
  Vector3,
  type Camera,
  type CubeTexture,
  type IUniform,
  type Texture,
  type WebGLRenderer,
} from 'three';
import { renderOrigin } from './renderOrigin';
import type { Submersion } from '../../sim/underwater/snellWindow';
import vertexShader from '../../../shaders/ocean.vert?raw';
import fragmentShader from '../../../shaders/ocean.frag?raw';
import { CHUNK_QUADS } from '../../sim/lod/lodBands';
import { FAR_FADE_END, FAR_FADE_START } from '../../sim/lod/farRings';
import { morphZones } from '../../sim/lod/lodMorph';
import { markOceanoMaterial } from '../underwater/sceneEncoding';
import type { WaveBinding } from '../waves/waveBinding';
import type { WaterVolumeUniforms } from '../underwater/waterVolumeUniforms';
import type { WakeUniforms } from '../wake/wakeUniforms';
import type { FoamUniforms } from '../foam/foamUniforms';
import { createSkyCubeUniforms, setSkyCube, type SkyCubeUniforms } from '../sky/skyCubeUniforms';
import type { PrefilteredSky } from '../sky/prefilteredSky';
import { setMaterialDefine } from '../shaders/materialDefines';
import { hazeExtinction } from '../../sim/optics/haze';
import { paramDefs } from '../../sim/params/params';

/** Lighter tint where the water faces the viewer, relative to the deep colour. */
const FACING_TINT_LIFT = new Color(0.045, 0.11, 0.12);

export class OceanMaterial extends ShaderMaterial {
  /**
   * The material of the grid bands whose vertices lie close enough together that ocean.frag's
   * per-pixel detail normals have weight 0 there (bandHasDetailNormals): compiled without that
   * block (OCEAN_NEAR_BANDS), since SwiftShader runs both sides of a branch, it shares this
   * material's uniforms object, so every setter here reaches it. It is itself for that material.
   */
  readonly near: OceanMaterial;
  /** The material whose uniforms `near` shares; null for the main one. */
  private readonly main: OceanMaterial | null;
  /** The last setSeenFromBelow's answer; null before the first. */
  private seenFrom: Submersion | null = null;
  /** Whether a sea of one roughness reads the sky prefiltered for it (src/render/sky/prefilteredSky.ts); a negative control turns it off. */
  prefiltering = true;
  /** The sky blurred for a sea of one roughness, once its code has arrived (the main material's, which `near` uses). */
  private prefiltered: PrefilteredSky | null = null;
  private disposed = false;
  /** Settles once the prefiltered sky's code has arrived (or failed to: the sky is then blended per pixel). */
  readonly ready: Promise<void>;

  constructor(
    private readonly waves: WaveBinding,
    fresnelTables: { fromAbove: Texture; fromBelow: Texture },
    sky: CubeTexture,
    shared: WaterVolumeUniforms & WakeUniforms & FoamUniforms & Record<'uSunColor', IUniform>,
    main: OceanMaterial | null = null,
  ) {
    super({
      vertexShader,
      fragmentShader,
      uniforms: {
        ...shared,
        ...createSkyCubeUniforms(sky),
        uPrefilteredSky: { value: null },
        uFresnelTable: { value: fresnelTables.fromAbove },
        uFresnelFromBelow: { value: fresnelTables.fromBelow },
        uFresnelEnabled: { value: true },
        uMarkSides: { value: false },
        uDeepColor: { value: new Color() },
        uFacingTint: { value: new Color() },
        uSunDirection: { value: new Vector3(0, 1, 0) },
        uHazeExtinction: { value: hazeExtinction(paramDefs.visibility.default * 1000) },
        uFlatNormals: { value: false },
        uChunkQuads: { value: CHUNK_QUADS },
        uOceanCenter: { value: new Vector2() },
        uFarFade: { value: new Vector2(FAR_FADE_START, FAR_FADE_END) },
        uRenderOrigin: { value: new Vector2() },
        uViewRelative: { value: new Matrix4() },
        uEyeRelative: { value: new Vector3() },
        uLodCamera: { value: new Vector3() },
        uLodHeight: { value: 0 },
        uMorphZones: { value: morphZones(1, 1, false) },
        uCrestHeight: { value: 1 },
      },
    });
    this.main = main;
    markOceanoMaterial(this);
    if (main) {
      this.uniforms = main.uniforms;
      this.defines.OCEAN_NEAR_BANDS = '';
    }
    waves.attach(this);
    this.near = main ? this : new OceanMaterial(waves, fresnelTables, sky, shared, this);
    // Fetched after the first frame, which blends two of the sky's levels per pixel: the same picture, dearer.
    this.ready = main ? Promise.resolve() : this.loadPrefilteredSky();
  }

  /** The binding's switches reach both programs; a caller detaching this one detaches both. */
  detachFrom(waves: WaveBinding): void {
    waves.detach(this);
    if (this.near !== this) waves.detach(this.near);
  }

  override dispose(): void {
    super.dispose();
    this.disposed = true;
    this.prefiltered?.dispose();
    if (this.near !== this) this.near.dispose();
  }

  /** After a lost WebGL context comes back: the prefiltered sky, which lived only in a render target, is painted again. */
  contextRestored(): void {
    this.prefiltered?.forget();
  }

  setWireframe(on: boolean): void {
    this.wireframe = on;
    this.near.wireframe = on;
  }

  /**
   * Where the shaders measure positions from, for an eye at (x, z): a point near the camera
   * (renderOrigin.ts), so that float32 keeps centimetres 10⁶ m out.
   */
  originFor: (x: number, z: number) => readonly [number, number] = renderOrigin;
  /** The height of the sea at rest (Ocean.update sets it from the ocean's position.y); the shaders work with the surface at y = 0. */
  seaLevel = 0;
  private readonly originShift = new Matrix4();
  private readonly eye = new Vector3();

  /**
   * Before each draw, for the camera drawing it: the render origin near that camera, the
   * view matrix for positions relative to it and the eye relative to it, all in double
   * precision here so that the shaders only see small numbers.
   */
  override onBeforeRender(renderer: unknown, _scene: unknown, camera: Camera): void {
    this.followWake();
    // A sixth of the model's largest height: about one standard deviation of height (the spectral
    // bounds are 6.6–7σ, src/sim/waves/spectra/spectralBounds.ts), for the subsurface glow.
    this.uniforms.uCrestHeight.value = Math.max(this.waves.model.model.bounds().vertical / 6, 0.01);
    // Foam as foam once its detail texture is there (shaders/foam/foamMaterial.glsl), paint until then.
    setMaterialDefine(this, 'OCEAN_FOAM_TEXTURE', this.uniforms.uFoamDetail.value !== null);
    // The highlights rolled off here only where the renderer has no tone curve of its own (ocean.frag).
    setMaterialDefine(this, 'OCEAN_OWN_ROLL_OFF', (renderer as WebGLRenderer).toneMapping === NoToneMapping);
    // A sea whose unresolved slopes are one number (the seed's) reads the sky blurred once for them.
    const { prefiltered, prefiltering } = this.main ?? this;
    prefiltered?.prepare(this, renderer as WebGLRenderer, prefiltering ? this.waves.model.uniformRoughness?.() : undefined);
    const eye = this.eye.setFromMatrixPosition(camera.matrixWorld);
    const [x, z] = (this.main ?? this).originFor(eye.x, eye.z);
    (this.uniforms.uRenderOrigin.value as Vector2).set(x, z);
    this.waves.model.setRenderOrigin?.(x, z);
    this.waves.model.setCamera?.(camera, renderer as WebGLRenderer);
    const seaLevel = (this.main ?? this).seaLevel;
    this.originShift.makeTranslation(x, seaLevel, z);
    (this.uniforms.uViewRelative.value as Matrix4).multiplyMatrices(camera.matrixWorldInverse, this.originShift);
    (this.uniforms.uEyeRelative.value as Vector3).set(eye.x - x, eye.y - seaLevel, eye.z - z);
  }

  /** Without its code the sea blends two of the sky's levels per pixel, as every other sea does. */
  private async loadPrefilteredSky(): Promise<void> {
    const { PrefilteredSky } = await import('../sky/prefilteredSky').catch(() => ({ PrefilteredSky: null }));
    if (PrefilteredSky && !this.disposed) this.prefiltered = new PrefilteredSky();
  }

  /** The sky prefiltered for this sea's one roughness, once its code has arrived (shared with `near`). */
  get prefilteredSky(): PrefilteredSky | null {
    return (this.main ?? this).prefiltered;
  }

  /**
   * Which faces are drawn, and shaded how, for where the view starts (OceanView's
   * submersion test). Above: front faces only, and the underside's shading is left out of the
   * program (ocean.frag). Straddling: both faces, the underside shaded from below, each face
   * marking its side in alpha for the underwater passes. Below (the eye and the whole near
   * plane in the water): a line of sight first meets the surface from below, where a front
   * face could only show behind a back face, so back faces only, and the shading from above
   * is left out of the program (OCEAN_ONLY_FROM_BELOW): SwiftShader would otherwise run it
   * for every pixel of the underside too.
   */
  setSeenFromBelow(where: Submersion): void {
    // Called every frame with, almost always, last frame's answer: nothing else writes these
    // (the side, uMarkSides, the two defines), so the same answer leaves them as they are.
    if (where === this.seenFrom) return;
    this.seenFrom = where;
    const inWater = where !== 'above';
    this.uniforms.uMarkSides.value = inWater;
    this.near.side = this.side = where === 'below' ? BackSide : inWater ? DoubleSide : FrontSide;
    this.setDefine('OCEAN_SEEN_FROM_BELOW', inWater);
    this.setDefine('OCEAN_ONLY_FROM_BELOW', where === 'below');
  }

  /** Compiles a define in or out of both programs (this one and `near`), which must draw alike. */
  private setDefine(name: string, on: boolean): void {
    for (const material of this.near === this ? [this] : [this, this.near]) setMaterialDefine(material, name, on);
  }

  setSky(sky: CubeTexture): void {
    setSkyCube(this.uniforms as SkyCubeUniforms, sky);
  }

  setWaterColor(hex: string): void {
    const deep = (this.uniforms.uDeepColor.value as Color).set(hex);
    (this.uniforms.uFacingTint.value as Color).copy(deep).add(FACING_TINT_LIFT);
  }

  setSunDirection(direction: readonly [number, number, number]): void {
    (this.uniforms.uSunDirection.value as Vector3).fromArray(direction).normalize();
  }

  setTeachingViews(flatNormals: boolean, showNormals: boolean): void {
    this.uniforms.uFlatNormals.value = flatNormals;
    this.setDefine('OCEAN_SHOW_NORMALS', showNormals);
  }

  /** The air's clarity: the haze's extinction at sea level for a visibility in km (shaders/haze.glsl). */
  setVisibility(kilometres: number): void {
    this.uniforms.uHazeExtinction.value = hazeExtinction(kilometres * 1000);
  }

  /** Thin sunlit crests glowing (shaders/subsurface.glsl), compiled in while on. */
  setSubsurface(enabled: boolean): void {
    this.setDefine('OCEAN_SUBSURFACE', enabled);
  }

  /** The spectral sea's wave groups: where whitecaps break, and far away which copy of the shorter tiles shows (shaders/foam/foamBreakup.glsl, shaders/waves/fft.glsl), compiled in while on. */
  setWaveGroups(enabled: boolean): void {
    this.setDefine('OCEAN_WAVE_GROUPS', enabled);
  }

  /** The spectral sea's foam left behind gathered into streaks along a strong wind (shaders/foam/foamWindrows.glsl), compiled in while on. */
  setWindrows(enabled: boolean): void {
    this.setDefine('OCEAN_WINDROWS', enabled);
  }

  /** waves=fft: slope normals on the left half of the screen, fabricated ones on the right. */
  setNormalsCompare(enabled: boolean): void {
    this.setDefine('OCEAN_NORMALS_COMPARE', enabled);
  }

  setFresnelEnabled(enabled: boolean): void {
    this.uniforms.uFresnelEnabled.value = enabled;
  }

  /** seaRoughness off: no slopes below the pixel but the sun's disc (OCEAN_SMOOTH_SEA, compiled in or out). */
  setSmoothSea(smooth: boolean): void {
    this.setDefine('OCEAN_SMOOTH_SEA', smooth);
  }

  /** The sky's reflection blurred by the roughness (a mip level of the cube), or sharp (OCEAN_SHARP_SKY). */
  setSkyBlur(blurred: boolean): void {
    this.setDefine('OCEAN_SHARP_SKY', !blurred);
  }

  /** The chunk grid's centre this frame, where the far rings' fade is measured from. */
  setOceanCenter(x: number, z: number): void {
    (this.uniforms.uOceanCenter.value as Vector2).set(x, z);
  }

  /**
   * The boat's wake is compiled into this program (OCEAN_WAKE) while the shared wake uniforms
   * hold a track to draw (uWakeCount ≥ 2), so that every ocean material, a compare strip's
   * too, draws the wake's heights, slope and foam from the same data. Off (the default view),
   * its code is left out: a software rasterizer compiles each program on its first draw, and
   * the wake's loops are a large part of that (docs/shader-notes.md). Turning the wake on or
   * off builds the other program once, on the next draw; three.js keeps both. Its GLSL arrives
   * with the wake's code (Ocean fetches it when the wake or the interactive waves are switched
   * on, src/render/shaders/lateChunks.ts): until then the program leaves it out.
   */
  private interactiveWavesOn = false;

  private followWake(): void {
    const wanted = (this.uniforms.uWakeCount.value as number) >= 2 || this.interactiveWavesOn;
    setMaterialDefine(this, 'OCEAN_WAKE', wanted && this.waves.late.has('oceano_wake'));
  }

  /**
   * Whether the interactive waves (iWave) are drawn: their code is compiled into both programs
   * (OCEAN_IWAVE) only while they are on, so that off, the programs are the ones without them.
   * Their slope reaches ocean.frag's per-pixel normals through the wake's (vWakeSlope), so
   * OCEAN_WAKE goes in alongside; with no wake track its loops are skipped (uWakeCount < 2).
   */
  setInteractiveWavesOn(on: boolean): void {
    for (const material of this.near === this ? [this] : [this, this.near]) material.interactiveWavesOn = on;
    this.setDefine('OCEAN_IWAVE', on);
  }

  /**
   * The water's own colour from its optics (OCEAN_WATER_OPTICS in ocean.frag), lit by the same
   * sun and sky as its glint, on every wave model; `picked`: the deep-water colour chosen by
   * hand instead (waterColorPicked), an artistic override.
   */
  setWaterColorPicked(picked: boolean): void {
    this.setDefine('OCEAN_WATER_OPTICS', !picked);
  }

  /**
   * Geomorphing's inputs this frame: the camera and wave height the bands were chosen with,
   * and each band's morph zone (src/sim/lod/lodMorph.ts morphZones).
   */
  setLodMorph(camera: readonly [number, number, number], height: number, zones: Float32Array): void {
    (this.uniforms.uLodCamera.value as Vector3).fromArray(camera);
    this.uniforms.uLodHeight.value = height;
    (this.uniforms.uMorphZones.value as Float32Array).set(zones);
  }

  /** The LOD debugger's view: each chunk tinted by its band (compiled in only while shown, see ocean.frag). */
  setLodColors(enabled: boolean): void {
    this.setDefine('OCEAN_LOD_COLORS', enabled);
  }
}
