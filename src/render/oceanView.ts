import { PerspectiveCamera, Scene, WebGLRenderer, type CubeTexture, type DataTexture } from 'three';
import type { OceanParams } from '../sim/params';
import type { OceanSurface } from '../sim/oceanSurface';
import { fresnelTable } from '../sim/fresnel';
import { sunDirection } from '../sim/sun';
import { OceanMaterial } from './oceanMaterial';
import { OceanChunks, type ChunkStats, type LodSettings } from './oceanChunks';
import { maxDisplacement } from '../sim/surface';
import { fresnelTexture, heightmapTexture } from './dataTextures';
import { SurfaceProbe } from './surfaceProbe';
import { HeightmapView } from './heightmapView';
import { SceneLights } from './sceneLights';
import type { SurfaceSample } from '../sim/oceanSurface';

export interface RenderStats extends ChunkStats {
  drawCalls: number;
  triangles: number;
}

/**
 * The three.js side of the ocean: renderer, scene, camera and the displaced chunks. It is
 * given its canvas, its surface data and the time of each frame; it reads no clock, URL
 * or DOM of its own.
 */
export class OceanView {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera: PerspectiveCamera;
  readonly fresnelData = fresnelTable(256);
  private readonly material: OceanMaterial;
  private readonly ocean: OceanChunks;
  private lod: LodSettings;
  private boundsHeight: number;
  private heightmapTextures: [DataTexture, DataTexture];
  private readonly fresnelTexture: DataTexture;
  private lastStats: RenderStats = { drawCalls: 0, triangles: 0, chunksTotal: 0, chunksVisible: 0, lodCounts: [] };
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
    this.ocean = new OceanChunks(this.material);
    this.scene.add(this.ocean.group);
    this.lod = params;
    this.boundsHeight = maxDisplacement(params);
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
    this.material.setLodColors(params.lodColors);
    this.lod = { lodDistance: params.lodDistance, lodBands: params.lodBands, lodBruteForce: params.lodBruteForce, freezeCulling: params.freezeCulling };
    // Chunk boxes reach as high and low as any wave can, so a crest rising into view is never culled.
    this.boundsHeight = maxDisplacement(params);
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
    this.ocean.update(this.camera, this.lod, this.boundsHeight);
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
    this.lastStats = { drawCalls: info.calls, triangles: info.triangles, ...this.ocean.stats() };
  }

  /** The displacement evaluated by the GPU shader at (x, z) points and a time. */
  probeSurface(points: readonly (readonly [number, number])[], time: number): SurfaceSample[] {
    this.probe ??= new SurfaceProbe(this.renderer);
    return this.probe.probe(points, this.surface.stateAt(time), this.heightmapTextures);
  }

  /**
   * CPU time of one chunk update (culling, bands, instance upload preparation) for the
   * current camera, ms: the median over `batches` batches of 20 updates, since the
   * browser's clock is too coarse to time a single one.
   */
  timeLodUpdate(batches = 25): number {
    const perBatch: number[] = [];
    for (let b = 0; b < batches; b++) {
      const start = performance.now();
      for (let k = 0; k < 20; k++) this.ocean.update(this.camera, this.lod, this.boundsHeight);
      perBatch.push((performance.now() - start) / 20);
    }
    perBatch.sort((a, c) => a - c);
    return perBatch[perBatch.length >> 1];
  }

  stats(): RenderStats {
    return { ...this.lastStats, lodCounts: this.lastStats.lodCounts.slice() };
  }

  dispose(): void {
    this.ocean.dispose();
    this.material.dispose();
    this.probe?.dispose();
    this.heightmapView?.dispose();
    for (const texture of this.heightmapTextures) texture.dispose();
    this.fresnelTexture.dispose();
    this.sky.dispose();
    this.renderer.dispose();
  }
}
