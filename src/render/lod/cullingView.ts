import { CameraHelper, Frustum, Matrix4, Vector3, type Object3D, type PerspectiveCamera } from 'three';
import { OCEAN_EXTENT, oceanOrigin } from '../../sim/lod/chunkSelection';
import type { Plane } from '../../sim/lod/frustumMath';

/**
 * The view the chunks are chosen for: the camera's frustum planes, its eye and the grid's
 * origin under it, captured from the camera each frame, or kept as they were while culling
 * is frozen.
 */
export class CullingView {
  readonly planes: Plane[] = Array.from({ length: 6 }, () => ({ nx: 0, ny: 0, nz: 1, d: 0 }));
  /** The eye the chunks' distances (their bands) are measured from. */
  readonly eye: [number, number, number] = [0, 0, 0];
  /** The chunk grid's south-west corner. */
  originX = 0;
  originZ = 0;
  private readonly frustum = new Frustum();
  private readonly viewProjection = new Matrix4();
  private readonly cameraPosition = new Vector3();
  /** The camera's position, quaternion, scale and projection matrix at the last capture (NaN: none yet). */
  private readonly lastCameraPose = new Float64Array(26).fill(NaN);
  private frozenHelper: CameraHelper | null = null;

  /** `parent`: where the frozen frustum is drawn. */
  constructor(private readonly parent: Object3D) {}

  /** Captures `camera`'s view, unless culling is `frozen` (then the view of the moment it froze stands). */
  update(camera: PerspectiveCamera, frozen: boolean): void {
    this.setFrozen(frozen, camera);
    if (!this.frozenHelper) this.capture(camera);
  }

  /** Makes the next update capture the camera again even if it has not moved. */
  forget(): void {
    this.lastCameraPose.fill(NaN);
  }

  dispose(): void {
    this.frozenHelper?.dispose();
  }

  private capture(camera: PerspectiveCamera): void {
    // A camera that has not moved since the last capture has the same frustum and origin, and
    // its world matrix is the one that capture made: the matrices need not be made again
    // (three's camera.updateMatrixWorld composes, decomposes and inverts, a good part of a
    // paused view's frame).
    if (this.sameCameraPose(camera)) return;
    camera.updateMatrixWorld();
    this.viewProjection.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    this.frustum.setFromProjectionMatrix(this.viewProjection);
    this.frustum.planes.forEach((plane, k) => {
      const target = this.planes[k];
      target.nx = plane.normal.x;
      target.ny = plane.normal.y;
      target.nz = plane.normal.z;
      target.d = plane.constant;
    });
    this.cameraPosition.setFromMatrixPosition(camera.matrixWorld).toArray(this.eye);
    [this.originX, this.originZ] = oceanOrigin(this.eye[0], this.eye[2]);
  }

  /**
   * Whether the camera's own transform and projection are those of the last capture; records
   * them. A camera with a parent (whose world matrix also depends on the parent's) never counts
   * as unmoved.
   */
  private sameCameraPose(camera: PerspectiveCamera): boolean {
    const last = this.lastCameraPose;
    const { position: p, quaternion: q, scale: s } = camera;
    const projection = camera.projectionMatrix.elements;
    let same =
      camera.parent === null &&
      last[0] === p.x &&
      last[1] === p.y &&
      last[2] === p.z &&
      last[3] === q.x &&
      last[4] === q.y &&
      last[5] === q.z &&
      last[6] === q.w &&
      last[7] === s.x &&
      last[8] === s.y &&
      last[9] === s.z;
    last[0] = p.x;
    last[1] = p.y;
    last[2] = p.z;
    last[3] = q.x;
    last[4] = q.y;
    last[5] = q.z;
    last[6] = q.w;
    last[7] = s.x;
    last[8] = s.y;
    last[9] = s.z;
    for (let i = 0; i < 16; i++) {
      same &&= last[10 + i] === projection[i];
      last[10 + i] = projection[i];
    }
    return same;
  }

  /**
   * "Freeze culling": keeps the frustum, eye and origin of the moment it was switched on, and
   * draws that frustum as lines (out to the ocean's edge), so orbiting away shows from outside
   * which chunks were chosen.
   */
  private setFrozen(frozen: boolean, camera: PerspectiveCamera): void {
    if (frozen === (this.frozenHelper !== null)) return;
    if (frozen) {
      this.capture(camera);
      const snapshot = camera.clone();
      snapshot.far = OCEAN_EXTENT / 2;
      snapshot.updateProjectionMatrix();
      snapshot.updateMatrixWorld();
      this.frozenHelper = new CameraHelper(snapshot);
      this.frozenHelper.update();
      this.parent.add(this.frozenHelper);
    } else if (this.frozenHelper) {
      this.parent.remove(this.frozenHelper);
      this.frozenHelper.dispose();
      this.frozenHelper = null;
    }
  }
}
