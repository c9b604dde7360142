import { Vector3, type PerspectiveCamera } from 'three';
import { fogHidingDistance } from '../../sim/underwater/waterFog';
import type { Submersion } from '../../sim/underwater/snellWindow';
import { DEFAULT_NEAR, nearForClearance } from './nearPlane';

/**
 * Past the far rings' skirt (src/sim/lod/farRings.ts), so the sea meets the horizon from 10 km
 * up. Depth precision is set by the near plane, not this (with far ≫ near).
 */
export const CAMERA_FAR = 1e9;

/**
 * The app camera's near and far planes, fitted to the eye's place over or under the water.
 * The library's Ocean leaves a user's camera alone; the app's view fits its own with this.
 */
export class EyeClearance {
  /** Off (a negative control), the near plane stays at 0.5 m however low the eye. */
  nearFitted = true;
  /** Off (a negative control), the far plane stays out under the water too. */
  farFitted = true;
  private readonly axis = new Vector3();

  /**
   * Brings the near plane in for an eye less than about a metre above the surface under it,
   * so that it stays above the water and the lower frame shows the surface from above
   * (nearPlane.ts); 0.5 m otherwise. The projection is remade only on a change, so a view that
   * keeps its near plane keeps its culling capture.
   */
  fitNear(camera: PerspectiveCamera, crestHeight: number, surfaceUnderEye: () => number): void {
    let near = DEFAULT_NEAR;
    // An eye this high over the highest crest keeps 0.5 m whichever way it looks (nearPlane.ts
    // needs at most 3.7 m of clearance per metre of near distance).
    if (this.nearFitted && camera.position.y < crestHeight + 2) {
      const clearance = camera.position.y - surfaceUnderEye();
      camera.updateMatrixWorld();
      const e = camera.matrixWorld.elements;
      near = nearForClearance(clearance, {
        forwardY: -e[9] / this.axis.set(e[8], e[9], e[10]).length(),
        upY: e[5] / this.axis.set(e[4], e[5], e[6]).length(),
        rightY: e[1] / this.axis.set(e[0], e[1], e[2]).length(),
        tanHalfFov: Math.tan((camera.fov * Math.PI) / 360),
        aspect: camera.aspect,
      });
    }
    if (near !== camera.near) {
      camera.near = near;
      camera.updateProjectionMatrix();
    }
  }

  /**
   * Wholly under the water, the far plane comes in to where the fog hides everything
   * (src/sim/underwater/waterFog.ts): the chunks beyond are culled and their empty pixels get
   * the water's colour from the underwater pass, as a surface that far would. Looking up from
   * below, the surface's far bands out to the horizon were most of the frame's vertex work.
   */
  fitFar(camera: PerspectiveCamera, submersion: Submersion, fogDensity: number): void {
    const below = submersion === 'below' && this.farFitted;
    const far = below ? Math.min(CAMERA_FAR, fogHidingDistance(fogDensity)) : CAMERA_FAR;
    if (far !== camera.far) {
      camera.far = far;
      camera.updateProjectionMatrix();
    }
  }
}
