import { WATER_IOR } from '../../sim/optics/fresnel';
import { SUN_IRRADIANCE } from '../../sim/optics/sun';
import { HIGHLIGHT_KNEE } from '../../sim/optics/highlightRollOff';
import { AEROSOL_SCALE_HEIGHT } from '../../sim/optics/haze';
import { SUN_DISC_COS_CORE, SUN_DISC_COS_EDGE, SUN_DISC_COS_MID, SUN_DISC_SLOPE_VARIANCE } from '../../sim/optics/sunDisc';
import { bodyColor } from '../../sim/optics/waterColor';
import { crestScattering, PARTICLE_MEAN_COSINE } from '../../sim/optics/subsurfaceGlow';
import { BLUR_MAX_TAPS } from '../underwater/blurLimits';
import { BAND_STEPS, BASE_STEP, DETAIL_NORMALS_FROM, LOD_BAND_COLORS, MAX_LOD_BANDS } from '../../sim/lod/lodBands';
import { GOD_RAY_RANGE } from '../underwater/godRayRange';
import { DEPTH_DARKENING, WATER_EXTINCTION } from '../../sim/underwater/waterFog';
import { TILE_COPY_TURN } from '../../sim/waves/fft/tileCopies';
import { FOAM_GROUP_SHARE_MEAN } from '../../sim/waves/fft/foamBreakup';
import { WINDROW_GATHER_FROM, WINDROW_GATHER_MEAN, WINDROW_GATHER_TO, WINDROW_SPACING } from '../../sim/waves/fft/windrows';

/** A GLSL float literal: always with a decimal point, since GLSL ES will not take `1` as a float. */
export function glslFloat(value: number): string {
  if (!Number.isFinite(value)) throw new RangeError(`No GLSL literal for ${value}.`);
  const text = String(value);
  return /[.e]/.test(text) ? text : `${text}.0`;
}

export function glslVec3(rgb: readonly [number, number, number]): string {
  return `vec3(${rgb.map(glslFloat).join(', ')})`;
}

/**
 * The constants GLSL shares with TypeScript, written as #defines from the TypeScript values
 * so that there is one source for each: `#include <oceano_constants>` (registered in
 * shaderChunks.ts). Guarded, since chunks that include it may be included together.
 */
export function shaderConstantsChunk(): string {
  return [
    '#ifndef OCEANO_CONSTANTS',
    '#define OCEANO_CONSTANTS',
    `#define WATER_IOR ${glslFloat(WATER_IOR)}`,
    `#define BLUR_MAX_TAPS ${BLUR_MAX_TAPS}`,
    `#define GOD_RAY_RANGE ${glslFloat(GOD_RAY_RANGE)}`,
    `#define WATER_EXTINCTION ${glslVec3(WATER_EXTINCTION)}`,
    `#define DEPTH_DARKENING ${glslVec3(DEPTH_DARKENING)}`,
    `#define SUN_IRRADIANCE ${glslFloat(SUN_IRRADIANCE)}`,
    `#define HIGHLIGHT_KNEE ${glslFloat(HIGHLIGHT_KNEE)}`,
    `#define AEROSOL_SCALE_HEIGHT ${glslFloat(AEROSOL_SCALE_HEIGHT)}`,
    `#define SUN_DISC_SLOPE_VARIANCE ${glslFloat(SUN_DISC_SLOPE_VARIANCE)}`,
    `#define SUN_DISC_COS_EDGE ${glslFloat(SUN_DISC_COS_EDGE)}`,
    `#define SUN_DISC_COS_CORE ${glslFloat(SUN_DISC_COS_CORE)}`,
    `#define SUN_DISC_COS_MID ${glslFloat(SUN_DISC_COS_MID)}`,
    `#define WATER_BODY_REFLECTANCE ${glslVec3(bodyColor())}`,
    `#define SUBSURFACE_SCATTER ${glslVec3(crestScattering())}`,
    `#define HENYEY_GREENSTEIN vec3(${[(1 - PARTICLE_MEAN_COSINE ** 2) / (4 * Math.PI), 1 + PARTICLE_MEAN_COSINE ** 2, 2 * PARTICLE_MEAN_COSINE].map(glslFloat).join(', ')})`,
    `#define TILE_COPY_TURN ${glslFloat(TILE_COPY_TURN)}`,
    `#define FOAM_GROUP_SHARE_MEAN ${glslFloat(FOAM_GROUP_SHARE_MEAN)}`,
    `#define WINDROW_SPACING ${glslFloat(WINDROW_SPACING)}`,
    `#define WINDROW_GATHER_FROM ${glslFloat(WINDROW_GATHER_FROM)}`,
    `#define WINDROW_GATHER_TO ${glslFloat(WINDROW_GATHER_TO)}`,
    `#define WINDROW_GATHER_MEAN ${glslFloat(WINDROW_GATHER_MEAN)}`,
    `#define DETAIL_NORMALS_FROM ${glslFloat(DETAIL_NORMALS_FROM)}`,
    `#define LOD_BAND_COUNT ${MAX_LOD_BANDS}`,
    `#define LOD_BASE_STEP ${glslFloat(BASE_STEP)}`,
    `#define LOD_BAND_STEPS int[${BAND_STEPS.length}](${BAND_STEPS.join(', ')})`,
    `#define LOD_BAND_COLORS vec3[${LOD_BAND_COLORS.length}](${LOD_BAND_COLORS.map(glslVec3).join(', ')})`,
    '#endif',
    '',
  ].join('\n');
}
