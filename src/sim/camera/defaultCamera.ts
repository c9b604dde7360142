/** Where the camera stands and what it looks at, in metres. */
export interface CameraPose {
  position: [number, number, number];
  target: [number, number, number];
}

/**
 * The view the page opens with: eye 9 m above the sea, looking out over it. The one
 * definition: the renderer's initial camera, "Surface" in the panel and the presets that
 * start from it all read this.
 */
export const DEFAULT_CAMERA: Readonly<CameraPose> = Object.freeze<CameraPose>({ position: [0, 9, 40], target: [0, 0, -60] });
