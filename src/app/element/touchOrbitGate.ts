import { TOUCH } from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';

/**
 * Touch on a figure in a page, as model-viewer has it: one finger passes over the figure as over
 * an image (a vertical swipe scrolls the page, a sideways one does nothing) until the reader taps
 * it. The tap gives the figure the focus, and while it keeps it one finger orbits and two zoom
 * and pan, as in the app. Two fingers orbit and pinch-zoom at any time: a deliberate gesture.
 * Returns the undo.
 */
export function gateTouchOrbit(controls: OrbitControls, canvas: HTMLCanvasElement): () => void {
  const engage = (engaged: boolean) => {
    controls.touches = engaged ? { ONE: TOUCH.ROTATE, TWO: TOUCH.DOLLY_PAN } : { ONE: null, TWO: TOUCH.DOLLY_ROTATE };
    // The element's stylesheet lets vertical swipes through to the page (pan-y); a tapped figure keeps them.
    if (engaged) canvas.style.setProperty('touch-action', 'none', 'important');
    else canvas.style.removeProperty('touch-action');
  };
  const onFocus = () => engage(true);
  const onBlur = () => engage(false);
  canvas.addEventListener('focus', onFocus);
  canvas.addEventListener('blur', onBlur);
  engage(document.activeElement === canvas);
  return () => {
    canvas.removeEventListener('focus', onFocus);
    canvas.removeEventListener('blur', onBlur);
  };
}
