import iwave from '../../../shaders/iwave.glsl?raw';
import { HAND_OVER_WIDTH } from '../../sim/iwave/kelvinHandOver';
import { CREST_COLOR, FOAM_FROM_SLOPE, STOKES_LIMIT_SLOPE, TINT_FROM_SLOPE, TINT_STRENGTH } from '../../sim/iwave/steepnessTint';
import { glslFloat } from '../shaders/shaderConstants';

/**
 * The text of `#include <oceano_iwave>` (shaders/iwave.glsl) with the numbers it shares with
 * TypeScript put before it as #defines. It travels with the interactive waves' code, fetched
 * when they are first switched on, and is handed to the ocean's late chunks then (src/render/shaders/lateChunks.ts).
 */
export function iwaveChunk(): string {
  return [
    `#define IWAVE_HAND_OVER_WIDTH ${glslFloat(HAND_OVER_WIDTH)}`,
    `#define IWAVE_TINT_FROM ${glslFloat(TINT_FROM_SLOPE)}`,
    `#define IWAVE_FOAM_FROM ${glslFloat(FOAM_FROM_SLOPE)}`,
    `#define IWAVE_STOKES_SLOPE ${glslFloat(STOKES_LIMIT_SLOPE)}`,
    `#define IWAVE_TINT_STRENGTH ${glslFloat(TINT_STRENGTH)}`,
    `#define IWAVE_CREST_COLOR vec3(${CREST_COLOR.map(glslFloat).join(', ')})`,
    iwave,
  ].join('\n');
}
