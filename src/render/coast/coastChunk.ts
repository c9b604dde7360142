import coast from '../../../shaders/coast.glsl?raw';
import { BEACH_SHORE_X, DUNE_HEIGHT, ISLAND_CENTER, ISLAND_HEIGHT, ISLAND_RADIUS, OFFSHORE_DEPTH } from '../../sim/coast/bathymetry';
import { diffuseAttenuation, SAND_ALBEDO } from '../../sim/coast/shallowWaterColor';
import { BREAKER_INDEX } from '../../sim/coast/windSeaDamping';
import { glslFloat, glslVec3 } from '../shaders/shaderConstants';

/**
 * The coast's GLSL (chunk `oceano_coast`, src/render/shaders/lateChunks.ts) with the constants
 * of its CPU twin written in as #defines, so both read one source: fetched only when
 * `bathymetry` is not `deep`.
 */
export const coastChunk = [
  `#define COAST_OFFSHORE_DEPTH ${glslFloat(OFFSHORE_DEPTH)}`,
  `#define COAST_BEACH_SHORE_X ${glslFloat(BEACH_SHORE_X)}`,
  `#define COAST_DUNE_HEIGHT ${glslFloat(DUNE_HEIGHT)}`,
  `#define COAST_ISLAND_CENTER vec2(${ISLAND_CENTER.map(glslFloat).join(', ')})`,
  `#define COAST_ISLAND_RADIUS ${glslFloat(ISLAND_RADIUS)}`,
  `#define COAST_ISLAND_HEIGHT ${glslFloat(ISLAND_HEIGHT)}`,
  `#define COAST_ATTENUATION ${glslVec3(diffuseAttenuation())}`,
  `#define COAST_BED_ALBEDO ${glslVec3(SAND_ALBEDO)}`,
  `#define COAST_BREAKER_INDEX ${glslFloat(BREAKER_INDEX)}`,
  coast,
].join('\n');
