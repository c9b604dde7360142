import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { Vector3, type PerspectiveCamera } from 'three';
import { DEFAULT_CAMERA, type CameraPose } from './cameraPose';

/** Where "Dive" puts the eye, metres below the mean sea level, and how far ahead it looks. */
const DIVE_DEPTH = 6;
const DIVE_LOOK_AHEAD = 60;

/**
 * OrbitControls around a target, with poses that restore exactly (shared links) and the panel's
 * "Dive". The controls' code is fetched after the first frame (a pointer is not needed to draw
 * it); until it arrives the camera looks at `target` and takes poses as they are given.
 */
export class OrbitCamera {
  private controls?: OrbitControls;
  private disposed = false;
  /** The point orbited. One vector for the camera's whole life: the boat's follower keeps it. */
  readonly target = new Vector3().fromArray(DEFAULT_CAMERA.target);
  /** The controls, once they answer the pointer (undefined if their code could not be had). */
  readonly loaded: Promise<OrbitControls | undefined>;
  private readonly exact = new Vector3();

  constructor(
    private readonly camera: PerspectiveCamera,
    canvas: HTMLCanvasElement,
    private readonly onChange: () => void,
  ) {
    camera.lookAt(this.target);
    this.loaded = import('three/addons/controls/OrbitControls.js').then(
      ({ OrbitControls }) => {
        if (this.disposed) return undefined;
        const pose = this.pose();
        const controls = new OrbitControls(camera, canvas);
        controls.target = this.target;
        // The whole sphere around the target: orbiting below its level takes the eye under the water.
        controls.maxPolarAngle = Math.PI;
        controls.addEventListener('change', onChange);
        this.controls = controls;
        this.setPose(pose);
        return controls;
      },
      (error) => {
        console.warn("Oceano: the camera's pointer controls could not be loaded; the camera keys still work.", error);
        return undefined;
      },
    );
  }

  setPose(pose: CameraPose): void {
    this.onChange();
    const camera = this.camera;
    camera.position.fromArray(pose.position);
    this.target.fromArray(pose.target);
    this.controls?.update();
    // The controls rebuild target and position through a length clamp and spherical angles,
    // which moves them by an ulp or so; put back the exact ones (unless the controls clamped
    // the angle) so that a shared link reproduces the view bit for bit.
    if (camera.position.distanceTo(this.exact.fromArray(pose.position)) < 1e-6) {
      this.target.fromArray(pose.target);
      camera.position.fromArray(pose.position);
      camera.lookAt(this.target);
    }
  }

  pose(): CameraPose {
    return { position: this.camera.position.toArray(), target: this.target.toArray() as [number, number, number] };
  }

  /** Moves eye and target together (the camera following the boat). */
  translate(dx: number, dz: number): void {
    if (dx === 0 && dz === 0) return;
    this.camera.position.x += dx;
    this.camera.position.z += dz;
    this.target.x += dx;
    this.target.z += dz;
    this.controls?.update();
  }

  /** Puts the eye DIVE_DEPTH under the mean sea level where it is, looking level the way it looked. */
  dive(): void {
    const eye = this.camera.position;
    const heading = this.target.clone().sub(eye).setY(0);
    if (heading.lengthSq() < 1e-12) heading.set(0, 0, -1);
    heading.normalize().multiplyScalar(DIVE_LOOK_AHEAD);
    this.setPose({ position: [eye.x, -DIVE_DEPTH, eye.z], target: [eye.x + heading.x, -DIVE_DEPTH, eye.z + heading.z] });
  }

  dispose(): void {
    this.disposed = true;
    this.controls?.removeEventListener('change', this.onChange);
    this.controls?.dispose();
  }
}
