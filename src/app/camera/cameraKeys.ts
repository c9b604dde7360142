import { orbit } from '../../sim/camera/cameraOrbit';
import type { CameraPose } from './cameraPose';

/** One key press (or one auto-repeat while held) turns the eye this far, radians (3°). */
const TURN = (3 * Math.PI) / 180;
/** One press moves the eye this factor closer (U) or farther (O). */
const ZOOM = 0.9;

/**
 * Keyboard camera: J/L orbit left and right about the target, I/K up and down, U/O move in
 * and out. Not the arrow keys, which steer the boat (boatSteering.ts). Each keydown,
 * auto-repeats included, is one step, so it works the same paused or playing. Keys typed
 * into a form field are left alone.
 */
export const CAMERA_KEYS: Record<string, { yaw: number; pitch: number; zoom: number }> = {
  KeyJ: { yaw: -TURN, pitch: 0, zoom: 1 },
  KeyL: { yaw: TURN, pitch: 0, zoom: 1 },
  KeyI: { yaw: 0, pitch: -TURN, zoom: 1 },
  KeyK: { yaw: 0, pitch: TURN, zoom: 1 },
  KeyU: { yaw: 0, pitch: 0, zoom: ZOOM },
  KeyO: { yaw: 0, pitch: 0, zoom: 1 / ZOOM },
};

export class CameraKeys {
  constructor(
    private readonly target: Window | HTMLElement,
    private readonly getPose: () => CameraPose,
    private readonly setPose: (pose: CameraPose) => void,
  ) {
    target.addEventListener('keydown', this.onKeyDown);
  }

  private readonly onKeyDown = (e: Event): void => {
    const event = e as KeyboardEvent;
    const element = event.target as HTMLElement | null;
    if (element && ['INPUT', 'TEXTAREA', 'SELECT'].includes(element.tagName)) return;
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    const step = CAMERA_KEYS[event.code];
    if (!step) return;
    event.preventDefault();
    const pose = this.getPose();
    this.setPose({ position: orbit(pose.position, pose.target, step.yaw, step.pitch, step.zoom), target: pose.target });
  };

  dispose(): void {
    this.target.removeEventListener('keydown', this.onKeyDown);
  }
}
