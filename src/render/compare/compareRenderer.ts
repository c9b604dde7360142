import { PerspectiveCamera, Vector2, type CubeTexture, type Scene, type WebGLRenderer } from 'three';
import type { OceanParams } from '../../sim/params/params';
import type { WavesChoice } from '../../sim/waves/waveModel';
import { compareModelNames, compareStrips, type Strip } from '../../sim/compare/compareLayout';
import type { PassTiming } from '../diagnostics/passTiming';
import { applyLook, type OceanEngine } from '../ocean/oceanEngine';
import { CompareSide } from './compareSide';
import { BASE_STEP, nearBandRefinement } from '../../sim/lod/lodBands';

/**
 * compare=a,b[,c]: the models after the first drawn side by side with the ocean's own, each
 * in its strip of columns. Each model culls its chunks to its own strip's frustum, so its
 * vertex work too is its strip's share; every pixel is drawn by exactly one model, with the
 * projection of the whole view, so a strip holds the same pixels as that model drawn alone.
 */
export class CompareRenderer {
  /** The models after the first (which is the ocean's own), left to right. */
  sides: CompareSide[] = [];
  /**
   * Whether a strip draws a chunk straddling it as the tiles that reach it (OceanChunks);
   * off, each strip draws its chunks whole (a diagnostic: what tiling saves).
   */
  stripCulling = true;
  private readonly bufferSize = new Vector2();
  private readonly cullCamera = new PerspectiveCamera();

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly scene: Scene,
    private readonly ocean: OceanEngine,
  ) {}

  /** Keeps one side per model after the first, in order, reusing those already made. */
  apply(params: OceanParams): void {
    const names = compareModelNames<WavesChoice>(params.compare).slice(1);
    const kept: CompareSide[] = [];
    const unused = [...this.sides];
    for (const name of names) {
      const k = unused.findIndex((side) => side.name === name);
      if (k >= 0) {
        kept.push(unused.splice(k, 1)[0]);
        continue;
      }
      const side = new CompareSide(name, params, this.renderer, this.ocean.materialInputs);
      this.scene.add(side.chunks.group);
      applyLook(side.material, params);
      kept.push(side);
    }
    for (const side of unused) side.dispose();
    this.sides = kept;
    for (const side of this.sides) side.view.setParams(params);
  }

  /** The look every material shows (sun, colour, teaching views) changed. */
  applyLook(params: OceanParams): void {
    for (const side of this.sides) applyLook(side.material, params);
  }

  setSky(sky: CubeTexture): void {
    for (const side of this.sides) side.material.setSky(sky);
  }

  advance(time: number): void {
    for (const side of this.sides) {
      side.view.update(time);
      // On a coast every strip's sea feels the same floor.
      this.ocean.coast?.dressSide(side.material, side.view.model);
    }
  }

  /** The strips of the frame, or null when there is nothing to compare; the splits are fractions of `[from, to]`, fractions of the width. */
  strips(params: Pick<OceanParams, 'compareSplit' | 'compareSplit2'>, [from, to]: readonly [number, number] = [0, 1]): Strip[] | null {
    if (this.sides.length === 0) return null;
    const width = this.renderer.getDrawingBufferSize(this.bufferSize).x;
    return compareStrips(this.sides.length + 1, params.compareSplit, params.compareSplit2, width, from * width, to * width);
  }

  /** Each model's chunks culled to its own strip. Bands and seams depend on distance alone, so a chunk reaching a strip is the one the model alone would draw there. */
  cull(strips: readonly Strip[], camera: PerspectiveCamera): void {
    const width = this.renderer.getDrawingBufferSize(this.bufferSize).x;
    strips.forEach((strip, i) => {
      if (strip.x1 <= strip.x0) return;
      const stripCamera = this.stripCamera(strip, width, camera);
      if (i === 0) this.ocean.cull(stripCamera, this.stripCulling);
      else {
        const side = this.sides[i - 1];
        side.chunks.update(
          stripCamera,
          this.ocean.lodSettings,
          this.ocean.grownByWake(side.bounds()),
          this.stripCulling,
          nearBandRefinement(side.view.finestVertexStep ?? BASE_STEP),
        );
      }
    });
  }

  /** The scene once per model, each with only its own ocean shown and the scissor its strip. */
  draw(strips: readonly Strip[], camera: PerspectiveCamera, afterStrip?: (model: string) => void): void {
    const size = this.renderer.getDrawingBufferSize(this.bufferSize);
    const ratio = this.renderer.getPixelRatio();
    const groups = [this.ocean.chunks.group, ...this.sides.map((side) => side.chunks.group)];
    const names = [this.ocean.waveModelView.name, ...this.sides.map((side) => side.name)];
    this.renderer.setScissorTest(true);
    try {
      strips.forEach((strip, i) => {
        if (strip.x1 <= strip.x0) return;
        groups.forEach((group, j) => (group.visible = i === j));
        // three multiplies the scissor by the pixel ratio and rounds: whole buffer pixels come back.
        this.renderer.setScissor(strip.x0 / ratio, 0, (strip.x1 - strip.x0) / ratio, size.y / ratio);
        this.renderer.render(this.scene, camera);
        afterStrip?.(names[i]);
      });
    } finally {
      this.renderer.setScissorTest(false);
      groups.forEach((group, j) => (group.visible = j === 0));
    }
  }

  /** The compared models' own GPU passes (a compared fft), each named after its model. */
  profilePasses(sync: () => void): PassTiming[] {
    return this.sides.flatMap((side) => (side.view.profilePasses?.(sync) ?? []).map((p) => ({ ...p, name: `${p.name} (${side.name})` })));
  }

  /** The camera narrowed to one strip's columns (setViewOffset): the frustum a strip's chunks are culled with. */
  private stripCamera(strip: Strip, width: number, camera: PerspectiveCamera): PerspectiveCamera {
    const stripCamera = this.cullCamera.copy(camera);
    // The full height from the camera's own aspect, so a fractional pixel ratio's rounded buffer cannot narrow the frustum.
    const fullHeight = width / camera.aspect;
    stripCamera.setViewOffset(width, fullHeight, strip.x0, 0, strip.x1 - strip.x0, fullHeight);
    stripCamera.updateMatrixWorld();
    return stripCamera;
  }

  /** After a lost WebGL context comes back: each compared model redoes what lived in render targets. */
  contextRestored(): void {
    for (const side of this.sides) {
      side.view.contextRestored?.();
      side.material.contextRestored();
    }
  }

  dispose(): void {
    for (const side of this.sides) side.dispose();
    this.sides = [];
  }
}
