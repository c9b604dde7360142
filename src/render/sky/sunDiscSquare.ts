import { Matrix4, Vector4, type Camera, type IUniform, type ShaderMaterial, type Vector2, type Vector3, type WebGLRenderer } from 'three';
import { SUN_DISC_COS_EDGE } from '../../sim/optics/sunDisc';
import { setMaterialDefine } from '../shaders/materialDefines';
import { runsHighlightRollOff } from '../tone/wholeFrameToneCurve';

/** How far from the sun's centre the square reaches: past the cube's soft edge, by a quarter. */
const REACH = 1.25 * Math.acos(SUN_DISC_COS_EDGE);
/** Pixels added on every side, so the edge's outermost pixel is inside the square. */
const MARGIN_PIXELS = 2;

/**
 * The square round the sun's disc where the sky draws the disc's edge antialiased: the disc is
 * thousands of times brighter than white, so a pixel its edge crosses, averaged in linear light,
 * is white however little of it the disc covers, and the edge steps by whole pixels. Where the
 * renderer runs our tone curve, the sky shows each pixel inside this square as its share of the
 * disc's white and the rest of the sky's shown colour (skyBackground.frag); elsewhere (a scene's
 * own curve, a pass into a render target) it draws the disc as the cube does. Placed here on the
 * CPU, before each render of the sky, so that only the square's pixels pay for the edge, in the
 * sky's own draw.
 */
export class SunDiscSquare {
  private readonly worldToClip = new Matrix4();
  private readonly viewport = new Vector4();
  private readonly clip = new Vector4();
  /** Off: no square, the edge as the sky draws it (a negative control, src/app/debug/shadingFaults.ts). */
  antialiased = true;

  /** `sky`: the sky material and its uniforms (uSunDirection, uDiscCentre, uDiscHalfSize). */
  constructor(private readonly sky: ShaderMaterial) {}

  /** Before each render of the sky: the tone curve's define, and the square as `camera` sees it in the current viewport. */
  beforeRender(renderer: WebGLRenderer, camera: Camera): void {
    setMaterialDefine(this.sky, 'OCEANO_DISC_THROUGH_ROLL_OFF', runsHighlightRollOff(renderer));
    renderer.getCurrentViewport(this.viewport);
    const u = this.sky.uniforms as Record<string, IUniform>;
    const halfSize = u.uDiscHalfSize.value as Vector2;
    // Out of sight: a square of no size, which holds no pixel.
    if (!this.place(camera, u.uSunDirection.value as Vector3, u.uDiscCentre.value as Vector2, halfSize)) halfSize.set(0, 0);
  }

  /** Puts the square round the sun's disc; false where it is out of sight. */
  private place(camera: Camera, sun: Vector3, centre: Vector2, halfSize: Vector2): boolean {
    if (!this.antialiased || sun.y < 0) return false;
    this.worldToClip.extractRotation(camera.matrixWorldInverse).premultiply(camera.projectionMatrix);
    const clip = this.clip.set(sun.x, sun.y, sun.z, 0).applyMatrix4(this.worldToClip);
    // w is the cosine of the sun's angle from the view's axis: behind the eye, or nearly square to it, nothing to draw.
    if (clip.w < 0.05) return false;
    centre.set(clip.x / clip.w, clip.y / clip.w);
    // A small angle r at an angle α from the axis spans at most P r / cos²α of the projection's scale P.
    const spread = Math.tan(REACH) / (clip.w * clip.w);
    const scale = camera.projectionMatrix.elements;
    const viewport = this.viewport;
    halfSize.set(scale[0] * spread + (2 * MARGIN_PIXELS) / viewport.z, scale[5] * spread + (2 * MARGIN_PIXELS) / viewport.w);
    return Math.abs(centre.x) - halfSize.x < 1 && Math.abs(centre.y) - halfSize.y < 1;
  }
}
