import {
  BufferAttribute,
  BufferGeometry,
  Matrix4,
  Mesh,
  ShaderMaterial,
  Vector2,
  Vector4,
  type Camera,
  type IUniform,
  type Vector3,
  type WebGLRenderer,
} from 'three';
import { SUN_DISC_COS_EDGE } from '../../sim/optics/sunDisc';
import vertexShader from '../../../shaders/sunDiscSprite.vert?raw';
import fragmentShader from '../../../shaders/skyBackground.frag?raw';
import { resolveChunks } from '../shaders/shaderChunks';
import { setMaterialDefine } from '../shaders/materialDefines';
import { markOceanoMaterial } from '../underwater/sceneEncoding';
import { runsHighlightRollOff } from '../tone/wholeFrameToneCurve';

/** How far from the sun's centre the square reaches: past the cube's soft edge, by a quarter. */
const REACH = 1.25 * Math.acos(SUN_DISC_COS_EDGE);
/** Pixels added on every side, so the edge's outermost pixel is inside the square. */
const MARGIN_PIXELS = 2;

/**
 * The sun's disc drawn again, over the sky behind the scene, with an antialiased edge: the disc
 * is thousands of times brighter than white, so a pixel its edge crosses, averaged in linear
 * light, is white however little of it the disc covers, and the edge steps by whole pixels.
 * Where the renderer runs our tone curve, this square shows each edge pixel as its share of the
 * disc's white and the rest of the sky's shown colour (skyBackground.frag). Elsewhere (a scene's
 * own curve, a pass into a render target) it draws what the sky draws. A child of the sky mesh,
 * so it is drawn wherever the sky is.
 */
export class SunDiscSprite {
  readonly mesh: Mesh<BufferGeometry, ShaderMaterial>;
  private readonly centre = new Vector2();
  private readonly halfSize = new Vector2();
  private readonly worldToClip = new Matrix4();
  private readonly viewport = new Vector4();
  private readonly clip = new Vector4();
  /** Off: no square, the edge as the sky draws it (a negative control, src/app/debug/shadingFaults.ts). */
  antialiased = true;

  /** `sky`: the sky material's uniforms (cube, sun, its radiance, the camera's rays), shared. */
  constructor(sky: Record<string, IUniform>, renderOrder: number) {
    const geometry = new BufferGeometry();
    geometry.setAttribute(
      'position',
      new BufferAttribute(new Float32Array([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0]), 3),
    );
    const material = markOceanoMaterial(
      new ShaderMaterial({
        vertexShader: resolveChunks(vertexShader),
        fragmentShader: resolveChunks(fragmentShader),
        uniforms: { ...sky, uDiscCentre: { value: this.centre }, uDiscHalfSize: { value: this.halfSize } },
        depthWrite: false,
      }),
    );
    this.mesh = new Mesh(geometry, material);
    this.mesh.name = 'oceano-sun-disc';
    this.mesh.frustumCulled = false;
    this.mesh.renderOrder = renderOrder;
    this.mesh.onBeforeRender = (renderer: WebGLRenderer, _scene, camera: Camera) => {
      setMaterialDefine(material, 'OCEANO_DISC_THROUGH_ROLL_OFF', runsHighlightRollOff(renderer));
      renderer.getCurrentViewport(this.viewport);
      const placed = this.place(camera, sky.uSunDirection.value as Vector3, this.antialiased ? this.viewport : null);
      // Nothing to draw while the disc is out of sight (three still counts the empty call).
      geometry.setDrawRange(0, placed ? 6 : 0);
    };
  }

  /** Puts the square round the sun's disc as `camera` sees it in `viewport` (px); false where it is out of sight. */
  private place(camera: Camera, sun: Vector3, viewport: Vector4 | null): boolean {
    if (!viewport || sun.y < 0) return false;
    this.worldToClip.extractRotation(camera.matrixWorldInverse).premultiply(camera.projectionMatrix);
    const clip = this.clip.set(sun.x, sun.y, sun.z, 0).applyMatrix4(this.worldToClip);
    // w is the cosine of the sun's angle from the view's axis: behind the eye, or nearly square to it, nothing to draw.
    if (clip.w < 0.05) return false;
    this.centre.set(clip.x / clip.w, clip.y / clip.w);
    // A small angle r at an angle α from the axis spans at most P r / cos²α of the projection's scale P.
    const spread = Math.tan(REACH) / (clip.w * clip.w);
    const scale = camera.projectionMatrix.elements;
    this.halfSize.set(scale[0] * spread + (2 * MARGIN_PIXELS) / viewport.z, scale[5] * spread + (2 * MARGIN_PIXELS) / viewport.w);
    return Math.abs(this.centre.x) - this.halfSize.x < 1 && Math.abs(this.centre.y) - this.halfSize.y < 1;
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    this.mesh.material.dispose();
  }
}
