import { Mesh, PerspectiveCamera, Scene, WebGLRenderer, type CubeTexture, type DataTexture } from 'three';
import type { OceanParams } from '../sim/params';
import type { OceanSurface } from '../sim/oceanSurface';
import { fresnelTable } from '../sim/fresnel';
import { sunDirection } from '../sim/sun';
import { OceanMaterial } from './oceanMaterial';
import { createGridGeometry } from './oceanGrid';
import { fresnelTexture, heightmapTexture } from './dataTextures';
import { SurfaceProbe } from './surfaceProbe';
import { HeightmapView } from './heightmapView';
import { SceneLights } from './sceneLights';
import type { SurfaceSample } from '../sim/oceanSurface';

/** Side of the displaced grid, metres, and its vertex spacing. */
const GRID_SIZE = 1000;
const GRID_SEGMENTS = 320;
const GRID_STEP = GRID_SIZE / GRID_SEGMENTS;

export interface RenderStats {
  drawCalls: number;
  triangles: number;
}

/**
 * The three.js side of the ocean: renderer, scene, camera and the displaced grid. It is
 * given its canvas, its surface data and the time of each frame; it reads no clock, URL
 * or DOM of its own.
 */
export class OceanView {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera: PerspectiveCamera;
  readonly fresnelData = fresnelTable(256);
  private readonly material: OceanMaterial;
  private readonly ocean: Mesh;
  private heightmapTextures: [DataTexture, DataTexture];
  private readonly fresnelTexture: DataTexture;
  private lastStats: RenderStats = { drawCalls: 0, triangles: 0 };
  private probe?: SurfaceProbe;
  private heightmapView?: HeightmapView;
  private showHeightmaps = false;
  private readonly lights: SceneLights;

  constructor(
    canvas: HTMLCanvasElement,
    private readonly surface: OceanSurface,
    private sky: CubeTexture,
    params: OceanParams,
  ) {
    this.renderer = new WebGLRenderer({ canvas, antialias: false, powerPreference: 'high-performance', preserveDrawingBuffer: true });
    this.renderer.info.autoReset = true;
    this.camera = new PerspectiveCamera(55, 16 / 9, 0.5, 20000);
    this.camera.position.set(0, 9, 40);
    this.camera.lookAt(0, 0, -60);

    this.scene.background = sky;
    this.heightmapTextures = surface.heightmaps.map(heightmapTexture) as [DataTexture, DataTexture];
    this.fresnelTexture = fresnelTexture(this.fresnelData);
    this.material = new OceanMaterial(this.heightmapTextures, this.fresnelTexture, sky);
    this.ocean = new Mesh(createGridGeometry(GRID_SIZE, GRID_SEGMENTS), this.material);
    // The grid follows the camera, so three's own bounds test would be against a stale box.
    this.ocean.frustumCulled = false;
    this.scene.add(this.ocean);
    this.lights = new SceneLights(this.scene);
    this.applyParams(params);
  }

  applyParams(params: OceanParams): void {
    if (this.surface.setParams(params)) {
      for (const texture of this.heightmapTextures) texture.dispose();
      this.heightmapTextures = this.surface.heightmaps.map(heightmapTexture) as [DataTexture, DataTexture];
      this.material.setHeightmaps(this.heightmapTextures);
    }
    this.material.setWaterColor(params.waterColor);
    const sun = sunDirection(params.sunElevation, params.sunAzimuth);
    this.material.setSunDirection(sun);
    this.lights.update(sun, params.waterColor);
    this.material.setFresnelEnabled(params.fresnel);
    this.material.wireframe = params.wireframe;
    this.material.setTeachingViews(params.normals === 'flat', params.shading === 'normals');
    this.showHeightmaps = params.view === 'heightmap';
  }

  setSky(sky: CubeTexture): void {
    this.sky.dispose();
    this.sky = sky;
    this.scene.background = sky;
    this.material.setSky(sky);
  }

  setSize(width: number, height: number, pixelRatio: number): void {
    const w = Math.max(1, Math.floor(width));
    const h = Math.max(1, Math.floor(height));
    this.renderer.setPixelRatio(pixelRatio);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  /**
   * The CPU half of a frame: everything that must be decided before drawing (surface
   * uniforms, grid placement). Kept apart from draw() so its cost can be measured alone.
   */
  update(time: number): void {
    this.material.setSurface(this.surface.stateAt(time));
    // Snapping to whole grid steps keeps every vertex on the same world lattice, so the
    // waves stay put under a moving camera instead of swimming.
    this.ocean.position.set(
      Math.round(this.camera.position.x / GRID_STEP) * GRID_STEP,
      0,
      Math.round(this.camera.position.z / GRID_STEP) * GRID_STEP,
    );
  }

  /** Submits the frame prepared by update() to the GPU. */
  draw(): void {
    if (this.showHeightmaps) {
      this.heightmapView ??= new HeightmapView();
      this.heightmapView.render(this.renderer, this.heightmapTextures, this.camera.aspect);
    } else {
      this.renderer.render(this.scene, this.camera);
    }
    const info = this.renderer.info.render;
    this.lastStats = { drawCalls: info.calls, triangles: info.triangles };
  }

  /** The displacement evaluated by the GPU shader at (x, z) points and a time. */
  probeSurface(points: readonly (readonly [number, number])[], time: number): SurfaceSample[] {
    this.probe ??= new SurfaceProbe(this.renderer);
    return this.probe.probe(points, this.surface.stateAt(time), this.heightmapTextures);
  }

  stats(): RenderStats {
    return { ...this.lastStats };
  }

  dispose(): void {
    this.ocean.geometry.dispose();
    this.material.dispose();
    this.probe?.dispose();
    this.heightmapView?.dispose();
    for (const texture of this.heightmapTextures) texture.dispose();
    this.fresnelTexture.dispose();
    this.sky.dispose();
    this.renderer.dispose();
  }
}
