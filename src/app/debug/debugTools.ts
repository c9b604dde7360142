import type { OceanApp } from '../oceanApp';
import type { PassTiming } from '../../render/diagnostics/passTiming';
import { profileFrame, timeLodUpdate } from '../../render/diagnostics/frameProfiler';
import { checkBatches } from '../api/apiChecks';
import { setShadingFixes, type ShadingFixes } from './shadingFaults';
import { countFrame, type FrameCounts } from '../../render/diagnostics/frameCounter';
import { drawPlantedPass } from './plantedPass';
import type { EncodedScene } from '../../render/underwater/underwaterPost';

/**
 * What `oceano.debug` does, in a module of its own: the page fetches it the first time a
 * debug call is made, so the product never carries the negative controls and diagnostics.
 */
export function debugTools(app: OceanApp) {
  const view = () => app.debugView();
  return {
    fresnelTable: (): Float32Array => view().ocean.fresnelData.slice(),
    fresnelTableFromBelow: (): Float32Array => view().ocean.fresnelFromBelowData.slice(),
    passTimings: (): PassTiming[] => profileFrame(view(), app.clock.time),
    heightmaps: (): { size: number; data: Float32Array }[] =>
      (view().waves.heightmaps ?? []).map((map) => ({ size: map.size, data: map.data.slice() })),
    /**
     * Draws one frame `seconds` (1/60 by default; 0: the same time again) after the clock's time,
     * its WebGL calls counted (src/render/diagnostics/frameCounter.ts). `plantedPass`: one render
     * more into a target of its own, a negative control.
     */
    frameCounts: (options: { seconds?: number; plantedPass?: boolean } = {}): FrameCounts => {
      const seconds = options.seconds ?? 1 / 60;
      if (!Number.isFinite(seconds) || seconds < 0) throw new Error(`frameCounts: seconds must be a number ≥ 0, got ${seconds}.`);
      app.clock.setTime(app.clock.time + seconds);
      return countFrame(view().renderer.getContext() as WebGL2RenderingContext, () => {
        app.renderFrame(false);
        if (options.plantedPass === true) drawPlantedPass(view().renderer);
      });
    },
    lodUpdateMs: (batches?: number): number => timeLodUpdate(view(), checkBatches(batches)),
    forceShaftLightWindow: (on: boolean): void => view().underwater.forceShaftLightWindow(on === true),
    setShadingFixes: (fixes: Partial<ShadingFixes>): void => setShadingFixes(view(), fixes),
    foamMemory: (): { n: number; texel: number; data: number[] } | null => {
      const memory = view().ocean.waveModelView.readFoamMemory?.();
      return memory ? { n: memory.n, texel: memory.texel, data: Array.from(memory.data) } : null;
    },
    /** How many times the sky prefiltered for the sea's one roughness has been painted (0 where the roughness varies by pixel). */
    prefilteredSkyPaints: (): number => view().ocean.material.prefilteredSky?.paintCount ?? 0,
    stripCulling: (on: boolean): void => void (view().stripCulling = on === true),
    /** The underwater passes' scene target: 'linear' (the library's default) or an encoded one (the app's). */
    underwaterScene: (mode: EncodedScene): void => view().underwater.setEncodedScene(mode),
  };
}

export type DebugTools = ReturnType<typeof debugTools>;
export type { ShadingFixes };
