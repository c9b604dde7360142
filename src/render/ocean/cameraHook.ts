import { Object3D, type Camera } from 'three';

/**
 * A child that three.js calls with every camera that renders its parent, while that render
 * gathers its objects: three's own hook for per-camera levels of detail (LOD.autoUpdate), which
 * its WebGL and WebGPU renderers call for any object flagged isLOD. An object's onBeforeRender
 * comes too late to choose chunks: by then the renderer has picked the meshes to draw and
 * uploaded their buffers. Being the first child, it runs before its siblings are gathered.
 */
export class CameraHook extends Object3D {
  readonly isLOD = true;
  readonly autoUpdate = true;

  constructor(private readonly onCamera: (camera: Camera) => void) {
    super();
    this.name = 'oceano-camera-hook';
    // Whatever layers the camera sees, the hook is called.
    this.layers.enableAll();
  }

  /** Called by the renderer, once per render, with the camera of that render. */
  update(camera: Camera): void {
    this.onCamera(camera);
  }
}
