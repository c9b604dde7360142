import type { OceanView } from '../ocean/oceanView';
import { median } from '../../sim/physics/sampleStatistics';
import type { PassTiming } from './passTiming';

/**
 * Draws one frame waiting for the GPU after each pass, and returns each pass's time. Above
 * the water the frame is the single direct render, 'scene', or with compare= one render per
 * strip, 'scene <model> strip'; a model with GPU passes of its own (waves=fft: 'fft', 'foam';
 * a compared one's with its name) reports those first.
 */
export function profileFrame(view: OceanView, time: number): PassTiming[] {
  const gl = view.renderer.getContext();
  const pixel = new Uint8Array(4);
  // Reading a canvas pixel waits for every command before it; each pass binds its own target again.
  const sync = () => {
    view.renderer.setRenderTarget(null);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  };
  view.update(time);
  const wavePasses = view.ocean.waveModelView.profilePasses?.(sync) ?? [];
  if (view.ocean.submersion !== 'above') {
    const passes = view.underwater.passes();
    if (!passes) throw new Error('The underwater passes are still loading: await oceano.ready, or draw a frame below the surface first.');
    return [...wavePasses, ...passes.profile(sync)];
  }
  view.underwater.resetEncoding();
  wavePasses.push(...(view.compare?.profilePasses(sync) ?? []));
  sync();
  let start = performance.now();
  const strips = view.splitStrips();
  if (strips && view.compare) {
    const passes: PassTiming[] = [];
    view.compare.draw(strips, view.camera, (model) => {
      sync();
      passes.push({ name: `scene ${model} strip`, ms: performance.now() - start });
      start = performance.now();
    });
    return [...wavePasses, ...passes];
  }
  view.renderer.render(view.scene, view.camera);
  sync();
  return [...wavePasses, { name: 'scene', ms: performance.now() - start }];
}

/**
 * Median CPU time of one full culling + LOD selection for the view's camera, ms (batches of
 * 20 for timer resolution). Each is made to select afresh: a still camera's frames reuse the
 * last selection and would time only the comparison that decides it.
 */
export function timeLodUpdate(view: OceanView, batches = 25): number {
  const perBatch: number[] = [];
  for (let b = 0; b < batches; b++) {
    const start = performance.now();
    for (let k = 0; k < 20; k++) {
      view.ocean.chunks.forgetSelection();
      view.ocean.cull(view.camera);
    }
    perBatch.push((performance.now() - start) / 20);
  }
  return median(perBatch);
}
