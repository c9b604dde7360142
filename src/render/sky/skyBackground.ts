import { BufferAttribute, BufferGeometry, Matrix4, Mesh, ShaderMaterial, Vector2, Vector3, type Camera, type CubeTexture } from 'three';
import { SUN_IRRADIANCE, SUN_LIGHT_COLOR } from '../../sim/optics/sun';
import { sunDiscRadiance } from '../../sim/optics/sunDisc';
import vertexShader from '../../../shaders/skyBackground.vert?raw';
import fragmentShader from '../../../shaders/skyBackground.frag?raw';
import { createSkyCubeUniforms, setSkyCube, type SkyCubeUniforms } from './skyCubeUniforms';
import { resolveChunks } from '../shaders/shaderChunks';
import { markOceanoMaterial } from '../underwater/sceneEncoding';
import type { SunDiscSquare } from './sunDiscSquare';

/** What scenes call the sky mesh, so a test can take it out (to see what is behind the sea). */
export const SKY_BACKGROUND_NAME = 'oceano-sky';

/**
 * Where the sky falls in the draw order: after the grid bands of the sea (gridBandBatch.ts, at
 * NEAR_SEA_RENDER_ORDER), before everything else. It is drawn at the far plane with the depth
 * test on, so the pixels those bands already cover are rejected before its shader runs, where
 * drawn first it was shaded under the whole sea. Everything that may lie at the far plane
 * itself (the far rings and the skirt, out to 10⁸ m, whose depth rounds to 1, the cleared
 * value) is still drawn after it, as before.
 */
export const SKY_RENDER_ORDER = -1;

/**
 * The sky drawn behind the scene: one screen-covering triangle that looks the
 * sky cube up along each pixel's exact view ray (shaders/skyBackground.*). It replaces
 * `scene.background`, whose unit box degenerates for a camera looking level along a 45°
 * diagonal (see the vertex shader).
 */
export class SkyBackground {
  readonly mesh: Mesh<BufferGeometry, ShaderMaterial>;
  /** Settles once the disc's square (src/render/sky/sunDiscSquare.ts, fetched on first use) is in place. */
  readonly ready: Promise<void>;
  private sunDisc: SunDiscSquare | null = null;
  private sunDiscEdge = true;
  private disposed = false;
  private readonly clipToWorld = new Matrix4();

  constructor(sky: CubeTexture) {
    const geometry = new BufferGeometry();
    // One triangle over the whole of clip space [-1, 1]².
    geometry.setAttribute('position', new BufferAttribute(new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), 3));
    const material = markOceanoMaterial(
      new ShaderMaterial({
        vertexShader: resolveChunks(vertexShader),
        fragmentShader: resolveChunks(fragmentShader),
        uniforms: {
          ...createSkyCubeUniforms(sky),
          uClipToWorldDirection: { value: this.clipToWorld },
          uSunDirection: { value: new Vector3(0, 1, 0) },
          uSunRadiance: { value: new Vector3() },
          // The square round the disc where its edge is antialiased (none until its code arrives).
          uDiscCentre: { value: new Vector2() },
          uDiscHalfSize: { value: new Vector2() },
        },
        depthWrite: false,
      }),
    );
    this.mesh = new Mesh(geometry, material);
    this.mesh.name = SKY_BACKGROUND_NAME;
    this.mesh.frustumCulled = false;
    this.mesh.renderOrder = SKY_RENDER_ORDER;
    // The camera of the render in progress (the view's own, a compare strip's, a composer pass's).
    this.mesh.onBeforeRender = (renderer, _scene, camera: Camera) => {
      // Directions only: the camera's rotation without its position, after the inverse projection.
      this.clipToWorld.extractRotation(camera.matrixWorld).multiply(camera.projectionMatrixInverse);
      this.sunDisc?.beforeRender(renderer, camera);
    };
    // The disc's edge antialiased in a square round it, in this same draw. Until its code
    // arrives (or if it never does) the sky's own edge shows.
    this.ready = import('./sunDiscSquare').then(
      ({ SunDiscSquare }) => {
        if (this.disposed) return;
        this.sunDisc = new SunDiscSquare(material);
        this.sunDisc.antialiased = this.sunDiscEdge;
      },
      () => undefined,
    );
  }

  /** Off: the disc's edge as the sky draws it, stepping by whole pixels (a negative control, src/app/debug/shadingFaults.ts). */
  setSunDiscEdge(antialiased: boolean): void {
    this.sunDiscEdge = antialiased;
    if (this.sunDisc) this.sunDisc.antialiased = antialiased;
  }

  private painted = false;
  private fullBrightness = true;

  /**
   * The sun the sky shows: `painted` for the sky painted from it, whose disc is drawn here in its
   * full brightness (the sun's irradiance over the disc's solid angle, in the sunlight's colour);
   * a cube map of the user's keeps the sun in its own pixels.
   */
  setSun(direction: readonly [number, number, number], painted: boolean): void {
    (this.mesh.material.uniforms.uSunDirection.value as Vector3).fromArray(direction).normalize();
    this.painted = painted;
    this.updateSunRadiance();
  }

  /** Off: the disc only as the cube holds it, white (1), as a negative control (src/app/debug/shadingFaults.ts). */
  setSunInFullBrightness(on: boolean): void {
    this.fullBrightness = on;
    this.updateSunRadiance();
  }

  private updateSunRadiance(): void {
    const radiance = this.painted && this.fullBrightness ? sunDiscRadiance(SUN_IRRADIANCE) : 0;
    (this.mesh.material.uniforms.uSunRadiance.value as Vector3).fromArray(SUN_LIGHT_COLOR).multiplyScalar(radiance);
  }

  setSky(sky: CubeTexture): void {
    setSkyCube(this.mesh.material.uniforms as SkyCubeUniforms, sky);
  }

  dispose(): void {
    this.disposed = true;
    this.mesh.geometry.dispose();
    this.mesh.material.dispose();
  }
}
