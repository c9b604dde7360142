import type { LiveWaveModel } from './waveModel';

/**
 * The last height asked of a wave model, kept while the model, its surface revision, the
 * point and the time are the same (LiveWaveModel.surfaceRevision: equal revisions give equal
 * heights). The view asks the height under the eye twice a frame (the near plane's fit, the
 * submersion test), and a paused view drawn again asks it again at the same time and place.
 */
export class SurfaceHeightMemo {
  private model: LiveWaveModel | null = null;
  private revision = Number.NaN;
  private time = Number.NaN;
  private x = Number.NaN;
  private z = Number.NaN;
  private last = Number.NaN;

  height(model: LiveWaveModel, x: number, z: number, time: number): number {
    if (model === this.model && model.surfaceRevision === this.revision && time === this.time && x === this.x && z === this.z)
      return this.last;
    const height = model.height(x, z, time);
    // Read after the height: taking it may compute the model's data (the FFT twin at a jump).
    this.revision = model.surfaceRevision;
    this.model = model;
    this.time = time;
    this.x = x;
    this.z = z;
    this.last = height;
    return height;
  }
}
