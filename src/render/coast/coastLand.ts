import { BufferAttribute, BufferGeometry, Color, DoubleSide, Mesh, ShaderMaterial, type IUniform } from 'three';
import vertexShader from '../../../shaders/coastLand.vert?raw';
import fragmentShader from '../../../shaders/coastLand.frag?raw';
import { resolveChunks } from '../shaders/shaderChunks';
import {
  BEACH_SHORE_X,
  DUNE_HEIGHT,
  ISLAND_CENTER,
  ISLAND_HEIGHT,
  ISLAND_RADIUS,
  seaDepth,
  type SeaFloor,
} from '../../sim/coast/bathymetry';
import { terrainBreaks } from '../../sim/coast/coastTerrain';
import { SAND_ALBEDO } from '../../sim/coast/shallowWaterColor';

/** How far inland the beach's land is drawn, and how far along the shore each way, metres: past the haze's reach. */
const BEACH_INLAND = 30_000;
const BEACH_ALONG = 30_000;
/** How deep the land mesh reaches under the still water, metres: below every trough the shallows hold. */
const UNDERWATER_DEPTH = 4;
/** Segments around the island. */
const ISLAND_SEGMENTS = 160;

/**
 * The coast's land: the sand of the beach up to its dune, or the island's hill, from
 * seaDepth, lit by the sun and the sky. It reaches a few metres under the still water, so no
 * gap opens between the sand and a trough at the shoreline; farther out the bed is seen
 * through the water's colour (shaders/coast.glsl), and from under the water the sea bed
 * (src/render/underwater/seaBed.ts) follows the same floor.
 */
export class CoastLand {
  readonly mesh: Mesh;
  private readonly material: ShaderMaterial;

  /** `look`: the ocean material's sky, sun and haze uniforms, shared so the land is lit as the sea is. */
  constructor(look: Record<string, IUniform>) {
    this.material = new ShaderMaterial({
      vertexShader,
      fragmentShader: resolveChunks(fragmentShader),
      side: DoubleSide,
      uniforms: {
        uSky: look.uSky,
        uSkyFlip: look.uSkyFlip,
        uSkySquared: look.uSkySquared,
        uSunDirection: look.uSunDirection,
        uSunColor: look.uSunColor,
        uHazeExtinction: look.uHazeExtinction,
        uSandAlbedo: { value: new Color(...SAND_ALBEDO) },
      },
    });
    this.mesh = new Mesh(new BufferGeometry(), this.material);
    this.mesh.name = 'oceano-coast-land';
    this.mesh.frustumCulled = false;
  }

  setFloor(floor: SeaFloor): void {
    this.mesh.geometry.dispose();
    this.mesh.geometry = floor.bathymetry === 'island' ? islandGeometry(floor) : beachGeometry(floor);
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    this.material.dispose();
  }
}

/** Columns at the profile's bends (x), two rows along the shore (z): every vertex on the ground. */
function beachGeometry(floor: SeaFloor): BufferGeometry {
  const columns = terrainBreaks(floor.beachSlope, DUNE_HEIGHT, BEACH_INLAND, UNDERWATER_DEPTH).map((s) => BEACH_SHORE_X - s);
  const rows = [-BEACH_ALONG, 0, BEACH_ALONG];
  return gridGeometry(columns.length, rows.length, (i, j) => [columns[i], rows[j]], floor);
}

/** Rings at the profile's bends around the island's centre, from its top to the shelf under the shallows. */
function islandGeometry(floor: SeaFloor): BufferGeometry {
  const radii = terrainBreaks(floor.beachSlope, ISLAND_HEIGHT, ISLAND_RADIUS, UNDERWATER_DEPTH)
    .map((s) => ISLAND_RADIUS + s)
    .filter((r) => r >= 0);
  // Two more rings on the hill, so its dome is round where it has no bend.
  const rings = [...new Set([0, ...radii, ISLAND_RADIUS / 3, (2 * ISLAND_RADIUS) / 3])].sort((a, b) => a - b);
  return gridGeometry(
    ISLAND_SEGMENTS + 1,
    rings.length,
    (i, j) => {
      const angle = (2 * Math.PI * i) / ISLAND_SEGMENTS;
      return [ISLAND_CENTER[0] + rings[j] * Math.cos(angle), ISLAND_CENTER[1] + rings[j] * Math.sin(angle)];
    },
    floor,
  );
}

/** A columns × rows grid of quads whose vertex (i, j) stands at place(i, j) on the ground. */
function gridGeometry(columns: number, rows: number, place: (i: number, j: number) => [number, number], floor: SeaFloor): BufferGeometry {
  const positions = new Float32Array(columns * rows * 3);
  for (let j = 0; j < rows; j++) {
    for (let i = 0; i < columns; i++) {
      const [x, z] = place(i, j);
      positions.set([x, -seaDepth(floor, x, z), z], (j * columns + i) * 3);
    }
  }
  const indices: number[] = [];
  for (let j = 0; j < rows - 1; j++) {
    for (let i = 0; i < columns - 1; i++) {
      const a = j * columns + i;
      const b = a + 1;
      const c = a + columns;
      const d = c + 1;
      indices.push(a, c, b, b, c, d);
    }
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setIndex(indices);
  return geometry;
}
