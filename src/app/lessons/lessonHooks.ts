import type { OceanParams, ParamKey } from '../../sim/params/params';
import type { Camera } from 'three';
import type { CameraPose } from '../camera/cameraPose';
import type { BoatInfo } from '../boat/boatController';

/** What the drawer asks of the app: open a lesson, change a parameter, place its labels on the sea. */
export interface LessonHooks {
  /** Resolves false, with a notice, for an unknown id. */
  openLesson(id: string): Promise<boolean>;
  onParam(key: ParamKey, value: OceanParams[ParamKey]): void;
  /** Opens the control panel's folders that hold `keys` (the lesson's controls) and folds the rest. */
  openFolders(keys: readonly ParamKey[]): void;
  /**
   * What the labels on the sea are placed from: the camera (three's, and its pose), the
   * canvas, the clock's time, the boat's pose and hull, and the height of the waves the
   * boat floats on at a point now; `stoneDropped`, when the last stone in the interactive
   * waves fell (null: none).
   */
  scene(): {
    camera: Camera;
    pose: CameraPose;
    canvas: HTMLCanvasElement;
    time: number;
    boat: BoatInfo;
    height(x: number, z: number): number;
    stoneDropped: number | null;
  };
}
