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
 * test on, so a GPU rejects the pixels those bands already cover before its shader runs, where
 * drawn first it was shaded under the whole sea (a software rasterizer shades them first: see
 * seaCoversBelowHorizon). Everything that may lie at the far plane itself (the far rings and the
 * skirt, out to 10⁸ m, whose depth rounds to 1, the cleared value) is still drawn after it.
 */
export const SKY_RENDER_ORDER = -1;

/**
 * How far below the horizontal the sky is still drawn where the sea lies under it all: sin 2°
 * of the ray at the screen's centre, so at least 1.4° anywhere on the screen (the rows at the
 * horizon keep the sky behind whatever the far sea leaves uncovered there).
 */
const BELOW_HORIZON_MARGIN = Math.sin((2 * Math.PI) / 180);

/** The full screen, [-1, 1]² in clip space, counter-clockwise. */
const SCREEN: readonly [number, number][] = [
  [-1, -1],
  [1, -1],
  [1, 1],
  [-1, 1],
];

/**
 * The part of the screen whose rays rise above `BELOW_HORIZON_MARGIN` under the horizontal, as
 * a fan of triangles (x, y, 0 per vertex): the screen clipped by the half-plane where the ray's
 * height, an affine function a x + b y + c of the clip coordinates, is at least 0. Empty where
 * the whole screen looks down.
 */
export function screenAboveLine(a: number, b: number, c: number): number[] {
  const height = ([x, y]: readonly [number, number]) => a * x + b * y + c;
  const polygon: [number, number][] = [];
  SCREEN.forEach((p, i) => {
    const q = SCREEN[(i + 1) % SCREEN.length];
    const [hp, hq] = [height(p), height(q)];
    if (hp >= 0) polygon.push([p[0], p[1]]);
    if (hp >= 0 !== hq >= 0) {
      const t = hp / (hp - hq);
      polygon.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
    }
  });
  const fan: number[] = [];
  for (let i = 1; i + 1 < polygon.length; i++) fan.push(...polygon[0], 0, ...polygon[i], 0, ...polygon[i + 1], 0);
  return fan;
}

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
  /**
   * Whether the sea covers every ray that points down, for the camera being drawn (set by the
   * ocean: its eye above the water, the sea drawn). Then the sky is drawn only above the
   * horizon's line. perf: a software rasterizer tests depth after the shader has run, so the
   * sky drawn over the whole screen was shaded under the whole sea too, 13 % of the default
   * view's frame (docs/light-cost.md); a GPU rejects those pixels before shading them, and
   * saves the rows' rasterization alone.
   */
  seaCoversBelowHorizon: () => boolean = () => false;
  private readonly fullScreen = [-1, -1, 0, 3, -1, 0, -1, 3, 0];

  constructor(sky: CubeTexture) {
    const geometry = new BufferGeometry();
    // One triangle over the whole of clip space [-1, 1]².
    // Up to three triangles, whose corners the vertex shader reads from uSkyCorners by gl_VertexID
    // (uniforms are set at the draw, where a buffer changed in onBeforeRender would be uploaded a frame late).
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(9 * 3), 3));
    geometry.setDrawRange(0, 3);
    const material = markOceanoMaterial(
      new ShaderMaterial({
        vertexShader: resolveChunks(vertexShader),
        fragmentShader: resolveChunks(fragmentShader),
        uniforms: {
          ...createSkyCubeUniforms(sky),
          uClipToWorldDirection: { value: this.clipToWorld },
          uSkyCorners: { value: Array.from({ length: 9 }, () => new Vector2()) },
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
      this.showAboveHorizon(this.seaCoversBelowHorizon());
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

  /**
   * The sky's triangles: over the whole screen, or where the sea covers every ray that points
   * down, over the screen above the line where the rays dip BELOW_HORIZON_MARGIN under the
   * horizontal (the ray's height, the second row of clipToWorld, is affine in clip x and y).
   */
  private showAboveHorizon(clipped: boolean): void {
    const e = this.clipToWorld.elements;
    const centreLength = Math.hypot(e[8] + e[12], e[9] + e[13], e[10] + e[14]);
    const corners = clipped ? screenAboveLine(e[1], e[5], e[9] + e[13] + BELOW_HORIZON_MARGIN * centreLength) : this.fullScreen;
    const uniform = this.mesh.material.uniforms.uSkyCorners.value as Vector2[];
    for (let i = 0; i < corners.length / 3; i++) uniform[i].set(corners[3 * i], corners[3 * i + 1]);
    this.mesh.geometry.setDrawRange(0, corners.length / 3);
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
