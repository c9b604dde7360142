/**
 * The keyboard's point on the sea, for those who place the tools without a mouse: the arrow
 * keys move it across the sea as the viewer sees it (↑ away from the eye, → to the right),
 * whatever way the camera faces, so the same key always moves it the same way on screen.
 */

export type CursorKey = 'ArrowUp' | 'ArrowDown' | 'ArrowLeft' | 'ArrowRight';

export function isCursorKey(key: string): key is CursorKey {
  return key === 'ArrowUp' || key === 'ArrowDown' || key === 'ArrowLeft' || key === 'ArrowRight';
}

/**
 * The move (dx, dz) in metres for one press of `key`, `metres` long, for an eye at `eye`
 * looking at `target`. Looking straight down, the view has no horizontal heading: ↑ is then −z
 * (north on the default view).
 */
export function cursorStep(key: CursorKey, eye: readonly number[], target: readonly number[], metres: number): [number, number] {
  let fx = target[0] - eye[0];
  let fz = target[2] - eye[2];
  const length = Math.hypot(fx, fz);
  if (length < 1e-9) {
    fx = 0;
    fz = -1;
  } else {
    fx /= length;
    fz /= length;
  }
  // Right of the heading (fx, fz) on the sea, seen from above with y up: (−fz, fx).
  const rx = -fz;
  const rz = fx;
  switch (key) {
    case 'ArrowUp':
      return [fx * metres, fz * metres];
    case 'ArrowDown':
      return [-fx * metres, -fz * metres];
    case 'ArrowRight':
      return [rx * metres, rz * metres];
    case 'ArrowLeft':
      return [-rx * metres, -rz * metres];
  }
}
