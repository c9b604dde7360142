import { Vector3, type PerspectiveCamera } from 'three';
import { classifyNearPlane, type Submersion } from '../../sim/underwater/snellWindow';
import { SurfaceHeightMemo } from '../../sim/waves/surfaceHeightMemo';
import type { LiveWaveModel } from '../../sim/waves/waveModel';
import { DEFAULT_NEAR } from './nearPlane';

/**
 * How far from the surface a near-plane sample must be to decide the whole near plane,
 * metres: it covers the surface rising or dipping between the 3 × 3 samples (spaced about
 * half a metre) on the steepest ripples.
 */
const WATERLINE_MARGIN = 0.25;
const NEAR_PLANE_SAMPLES: readonly [number, number][] = [-1, 0, 1].flatMap((x) => [-1, 0, 1].map((y) => [x, y] as [number, number]));

export interface EyePlace {
  /** The eye is below the surface at its own (x, z). */
  underwater: boolean;
  /** 'above' or 'below' when the eye and its whole near plane are clear of the surface on one side; 'straddling' when the waterline may cross the frame. */
  submersion: Submersion;
  /** Height of the surface under the eye, metres. */
  eyeSurface: number;
}

/**
 * Which side of the water a camera sees from, by the waves' CPU twin: the eye's own point,
 * and when the surface is within reach of the near plane, 3 × 3 points on it.
 */
export class EyeSubmersion {
  private readonly memo = new SurfaceHeightMemo();
  private readonly point = new Vector3();

  /** Height of the surface under (x, z) at `time`, kept while nothing it depends on changes. */
  surfaceUnder(waves: LiveWaveModel, x: number, z: number, time: number): number {
    return this.memo.height(waves, x, z, time);
  }

  locate(camera: PerspectiveCamera, waves: LiveWaveModel, crestHeight: number, time: number): EyePlace {
    const eye = camera.position;
    const eyeSurface = this.surfaceUnder(waves, eye.x, eye.z, time);
    const underwater = eye.y < eyeSurface;
    // The near plane lies within `reach` of the eye: far above the highest crest, no sampling needed.
    const nearHalfHeight = camera.near * Math.tan((camera.fov * Math.PI) / 360);
    const reach = Math.hypot(camera.near, nearHalfHeight, nearHalfHeight * camera.aspect);
    // The samples are spaced in proportion to the near distance, and so is what the surface can do between them.
    const margin = WATERLINE_MARGIN * (camera.near / DEFAULT_NEAR);
    if (eye.y - reach > crestHeight + margin) return { underwater, submersion: 'above', eyeSurface };
    camera.updateMatrixWorld();
    const points = [{ y: eye.y, surface: eyeSurface }];
    for (const [x, y] of NEAR_PLANE_SAMPLES) {
      const p = this.point.set(x, y, -1).unproject(camera);
      points.push({ y: p.y, surface: waves.height(p.x, p.z, time) });
    }
    return { underwater, submersion: classifyNearPlane(points, margin), eyeSurface };
  }
}
