import type { Camera, IUniform, Texture, WebGLRenderer } from 'three';
import type { PassTiming } from '../diagnostics/passTiming';
import type { OceanParams } from '../../sim/params/params';
import type { LiveWaveModel, WavesChoice } from '../../sim/waves/waveModel';

/**
 * The render side of one wave model: the GPU half of the seam whose CPU half is
 * src/sim/waves/waveModel.ts. It owns its GLSL chunk (`chunk`, named `chunkName`), the uniforms and textures that chunk reads, and whatever GPU work a frame
 * needs before drawing (update). Every shader that needs the waves writes
 * `#include <oceano_waves>`; WaveBinding points that include at the active model's chunk.
 *
 * The chunk defines, in terms of the undisplaced grid point:
 *   vec3 waveDisplacement(vec2 gridXZ);  // (dx, dy, dz): the vertex goes to grid + d
 *   vec3 waveNormal(vec2 gridXZ);        // unit normal of the displaced surface there
 *   float waveLensHeight(vec2 worldXZ);  // short waves' height: focuses the god-ray shafts
 *   float waveUnresolvedSlopeVariance(); // ocean.frag's pixels: the mean-square slope the normal
 *                                        // leaves out (Cox & Munk's σ² less what it shows),
 *                                        // the glint's and the sky reflection's roughness
 * and nothing else that other shaders may rely on (helpers stay private by convention).
 * A chunk that defines WAVE_PIXEL_NORMALS also defines, for ocean.frag's pixels,
 *   void wavePixelFields(vec2 relativeXZ, bool near); // reads the pixel's fields once, first
 *   vec3 waveNormalNear(vec2 relativeXZ); // waveNormal at the render origin + relativeXZ
 * (and with WAVE_FOAM, waveFoamNear), fed the origin by setRenderOrigin.
 */
export interface WaveModelView {
  readonly name: WavesChoice;
  /** The CPU twin this view draws; the boat, the underwater switch and the API sample it. */
  readonly model: LiveWaveModel;
  /** A name for this model's GLSL, e.g. 'oceano_waves_seed' (program cache keys tell models apart by it). */
  readonly chunkName: string;
  /** The model's GLSL, put where a shader writes `#include <oceano_waves>`. */
  readonly chunk: string;
  /** What the chunk reads. The same objects go into every material bound to this model. */
  readonly uniforms: Readonly<Record<string, IUniform>>;
  /**
   * Metres after which waveLensHeight repeats along x and along z, or null where it does not
   * repeat. The underwater shaft light is baked over one period when it is small enough, else
   * over a window around the camera (src/render/underwater/shaftLightTile.ts).
   */
  readonly lensPeriod: number | null;
  /** Textures the "heightmap" teaching view shows, where the model has any. */
  readonly heightmapTextures?: readonly [Texture, Texture];
  /**
   * Where those textures keep the height and what value the view draws white (its negative
   * black), per texture. Absent: channel 0 (r), ±1 (the seed's Perlin maps).
   */
  readonly heightmapLayout?: HeightmapLayout;
  /**
   * The spacing, metres, the vertices near the eye need to draw the model's steepest short
   * waves (src/sim/lod/lodBands.ts nearBandRefinement splits the nearest band's quads to reach
   * it, down to 0.5 m). Absent: the grid's 2 m does.
   */
  readonly finestVertexStep?: number;
  /** Passes new parameters to the model and re-uploads whatever they changed. */
  setParams(params: OceanParams): void;
  /** Prepares the uniforms (and any GPU passes) for a frame at `time`, seconds. */
  update(time: number): void;
  /**
   * The mean-square slope of the waves the normals leave out, where it is one number for the
   * whole sea (the seed's): the sky it reflects is then blurred once for it, not per pixel
   * (src/render/sky/prefilteredSky.ts). Absent where it varies from pixel to pixel.
   */
  uniformRoughness?(): number;
  /**
   * The render origin (src/render/ocean/renderOrigin.ts) the ocean's pixels measure their grid points
   * from, before each draw (OceanMaterial.onBeforeRender): a model with per-pixel normals
   * folds it into its phases in double precision. Absent where nothing is evaluated per pixel.
   */
  setRenderOrigin?(x: number, z: number): void;
  /**
   * The camera about to draw and its renderer (OceanMaterial.onBeforeRender), for a model that
   * filters per vertex what a pixel cannot resolve (WAVE_VERTEX_SLOPES): the pixel's angle.
   */
  setCamera?(camera: Camera, renderer: WebGLRenderer): void;
  /**
   * For the profiler (oceano.debug.passTimings, `npm run bench`): runs this frame's GPU
   * passes once more, giving the same textures, calling `sync` (which waits for the GPU)
   * after each group, and returns each group's time. Absent for models with no GPU passes.
   */
  profilePasses?(sync: () => void): PassTiming[];
  /** For oceano.debug.foamMemory: the remembered foam's tile (n × n potentials, row by row, texels `texel` m wide), where the model remembers foam. */
  readFoamMemory?(): { n: number; texel: number; data: Float32Array };
  /** For the foam drift's negative control (oceano.debug.setShadingFixes({ foamDrift: false })): the remembered foam drifts or stays put. */
  setFoamDrift?(on: boolean): void;
  /**
   * After a lost WebGL context comes back: what the model's GPU passes drew into render
   * targets is gone, so the next update must draw it again even at the same time. Absent
   * where nothing lives only in render targets.
   */
  contextRestored?(): void;
  dispose(): void;
}

export interface HeightmapLayout {
  /** 0: the height is in r; 1: in g (the FFT's (dx, dy, dz, ·) textures). */
  channel: 0 | 1;
  /** Height drawn white in each texture, m. */
  range: readonly [number, number];
}
