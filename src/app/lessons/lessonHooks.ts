import type { OceanParams, ParamKey } from '../../sim/params/params';
import type { CameraPose } from '../camera/cameraPose';

/** Where a legend's label goes: a world point's position on the canvas in CSS pixels, or null when it is behind the camera. */
export type ProjectToCanvas = (x: number, y: number, z: number) => [number, number] | null;

/** What the drawer asks of the app: open a lesson, change a parameter, place its labels on the sea. */
export interface LessonHooks {
  openLesson(id: string): boolean;
  onParam(key: ParamKey, value: OceanParams[ParamKey]): void;
  /** Opens the control panel's folders that hold `keys` (the lesson's controls) and folds the rest. */
  openFolders(keys: readonly ParamKey[]): void;
  project: ProjectToCanvas;
  /** The boat's position (x, z) and heading in radians, for the wake guide's labels. */
  boat(): { x: number; z: number; heading: number };
  camera(): CameraPose;
}
