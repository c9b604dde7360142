import { RedFormat, RepeatWrapping, type CubeTexture, type DataTexture, type WebGLRenderer } from 'three';
import type { OceanParams } from '../../sim/params/params';
import type { Rect } from '../../sim/layout/rect';
import { noiseStages, type NoiseStages } from '../../sim/noise/noiseStages';
import { HEIGHTMAP_SIZE, surfaceStateAt } from '../../sim/waves/seed/seedSurface';
import { crossPlacement, figurePictures, SKY_CUBE_VIEW, type PictureId } from '../../sim/teaching/teachingFigures';
import { floatTexture } from '../optics/dataTextures';
import type { WaveModelView } from '../waves/waveModelView';
import { CubeCrossFigure } from './cubeCrossFigure';
import { PanelFigure, type Panel } from './panelFigure';

/** What a teaching view is drawn from: the parameters and time of the frame, the model and sky on screen, where there is room. */
export interface FigureInput {
  params: OceanParams;
  time: number;
  waves: WaveModelView;
  sky: CubeTexture;
  /** The part of the canvas the panel and the lessons drawer leave free, CSS px. */
  free: Rect;
  /** The canvas's CSS size. */
  canvas: { width: number; height: number };
}

type StageTextures = Record<keyof NoiseStages, DataTexture>;

/**
 * What the canvas shows when `view` is not the sea: the active model's heightmaps, the
 * Perlin noise step by step (computed from the seed by the noise code itself), or the sky's
 * cube map unfolded. Each is laid out in the free part of the canvas.
 */
export class TeachingFigure {
  private panels?: PanelFigure;
  private cross?: CubeCrossFigure;
  private stages: { seed: number; textures: StageTextures } | null = null;

  /** Draws the figure; false where the view has nothing to show (a model without heightmaps). */
  draw(renderer: WebGLRenderer, input: FigureInput): boolean {
    const { params, free, canvas } = input;
    if (params.view === SKY_CUBE_VIEW) {
      this.cross ??= new CubeCrossFigure(input.sky);
      this.cross.render(renderer, input.sky, crossPlacement(free).box, canvas);
      return true;
    }
    const pictures = figurePictures(params.view, free);
    const panels = pictures.map(({ id, rect }) => this.panel(id, input, rect));
    if (pictures.length === 0 || panels.includes(null)) return false;
    const channel = pictures[0].id === 'heightmap0' ? (input.waves.heightmapLayout?.channel ?? 0) : 0;
    this.panels ??= new PanelFigure();
    this.panels.render(renderer, panels as Panel[], canvas, channel);
    return true;
  }

  private panel(id: PictureId, input: FigureInput, rect: Rect): Panel | null {
    if (id === 'heightmap0' || id === 'heightmap1') {
      const index = id === 'heightmap0' ? 0 : 1;
      const maps = input.waves.heightmapTextures;
      return maps ? { rect, first: maps[index], range: input.waves.heightmapLayout?.range[index] ?? 1 } : null;
    }
    const textures = this.stageTextures(input.params.seed);
    if (id === 'first') return { rect, first: textures.octaves };
    // The weight the sea mixes its two heightmaps with at this instant (seedSurface.ts).
    if (id === 'blend')
      return { rect, first: textures.octaves, second: textures.second, weight: surfaceStateAt(input.params, input.time).rippleBlend };
    return { rect, first: textures[id] };
  }

  /** The stages of the noise for `seed`, computed and uploaded the first time that seed is shown. */
  private stageTextures(seed: number): StageTextures {
    if (this.stages?.seed === seed) return this.stages.textures;
    this.disposeStages();
    const stages = noiseStages(seed, HEIGHTMAP_SIZE);
    const upload = ({ size, data }: { size: number; data: Float32Array }) => floatTexture(data, size, size, RedFormat, RepeatWrapping);
    const textures: StageTextures = {
      hash: upload(stages.hash),
      smoothed: upload(stages.smoothed),
      interpolated: upload(stages.interpolated),
      octaves: upload(stages.octaves),
      second: upload(stages.second),
    };
    this.stages = { seed, textures };
    return textures;
  }

  private disposeStages(): void {
    for (const texture of Object.values(this.stages?.textures ?? {})) texture.dispose();
    this.stages = null;
  }

  dispose(): void {
    this.disposeStages();
    this.panels?.dispose();
    this.cross?.dispose();
  }
}
