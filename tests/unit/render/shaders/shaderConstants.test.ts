import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { glslFloat, shaderConstantsChunk } from '../../../../src/render/shaders/shaderConstants';
import { WATER_IOR } from '../../../../src/sim/optics/fresnel';
import { BLUR_MAX_TAPS } from '../../../../src/render/underwater/gaussianKernel';
import { GOD_RAY_RANGE } from '../../../../src/render/underwater/shaftLightTile';
import { BAND_STEPS, LOD_BAND_COLORS, MAX_LOD_BANDS } from '../../../../src/sim/lod/lodBands';

const SHADER_DIR = join(__dirname, '../../../../shaders');

function shaderFiles(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) =>
    entry.isDirectory() ? shaderFiles(join(dir, entry.name)) : [join(dir, entry.name)],
  );
}

/** Literal copies of the shared constants that a shader must not carry (they come from oceano_constants). */
function copiesIn(source: string): string[] {
  const found: string[] = [];
  if (/\b1\.333\b/.test(source)) found.push('index of refraction 1.333');
  // The tap count is a small number found everywhere: a copy shows as an array size or a loop bound.
  if (new RegExp(`\\[\\s*${BLUR_MAX_TAPS}\\s*\\]|<\\s*${BLUR_MAX_TAPS}\\b|MAX_TAPS\\s+${BLUR_MAX_TAPS}\\b`).test(source)) found.push(`blur taps ${BLUR_MAX_TAPS}`);
  if (new RegExp(`=\\s*${GOD_RAY_RANGE}\\.0\\b`).test(source)) found.push(`god-ray range ${GOD_RAY_RANGE}`);
  // The band steps, in order within one statement (a list, or a chain of ternaries by band).
  if (new RegExp(BAND_STEPS.map((step) => `\\b${step}\\b`).join('[^;]*?')).test(source)) found.push('band steps');
  // The band count, or the last grid band, as a literal: a band compared with a number.
  if (/\bband\s*(<|<=|>|>=|==)\s*\d/.test(source)) found.push('band count');
  for (const rgb of LOD_BAND_COLORS) {
    if (source.includes(`vec3(${rgb.map(glslFloat).join(', ')})`)) found.push(`band colour ${rgb.join(', ')}`);
  }
  return found;
}

describe('constants shared by TypeScript and GLSL', () => {
  it('are written into the oceano_constants chunk from the TypeScript values', () => {
    const chunk = shaderConstantsChunk();
    expect(chunk).toContain(`#define WATER_IOR ${WATER_IOR}`);
    expect(chunk).toContain(`#define BLUR_MAX_TAPS ${BLUR_MAX_TAPS}`);
    expect(chunk).toContain('#define GOD_RAY_RANGE 60.0');
    expect(chunk).toContain('#define LOD_BAND_COLORS vec3[6](vec3(0.95, 0.2, 0.15), vec3(0.95, 0.6, 0.1),');
    expect(LOD_BAND_COLORS).toHaveLength(MAX_LOD_BANDS);
  });

  it('give ocean.vert the bands of src/sim/lod/lodBands.ts: their count and every vertex step', () => {
    const chunk = shaderConstantsChunk();
    expect(chunk).toContain(`#define LOD_BAND_COUNT ${MAX_LOD_BANDS}\n`);
    expect(chunk).toContain(`#define LOD_BAND_STEPS int[${MAX_LOD_BANDS}](${BAND_STEPS.join(', ')})\n`);
    expect(chunk).toContain('#define LOD_BAND_STEPS int[6](1, 2, 3, 6, 12, 24)\n');
    const vertex = readFileSync(join(SHADER_DIR, 'ocean.vert'), 'utf8');
    expect(vertex).toContain('#include <oceano_constants>');
    expect(vertex).toMatch(/const int BAND_STEPS\[LOD_BAND_COUNT\] = LOD_BAND_STEPS;/);
  });

  it('are written as GLSL float literals', () => {
    expect(glslFloat(1)).toBe('1.0');
    expect(glslFloat(1.333)).toBe('1.333');
    expect(glslFloat(1e-7)).toBe('1e-7');
    expect(() => glslFloat(Number.NaN)).toThrow();
  });

  it('appear in no shader file as literal copies', () => {
    const offenders = shaderFiles(SHADER_DIR).flatMap((file) => copiesIn(readFileSync(file, 'utf8')).map((what) => `${file}: ${what}`));
    expect(offenders).toEqual([]);
  });

  it('would be caught if copied into a shader again (negative control)', () => {
    expect(copiesIn('const float WATER_OVER_AIR = 1.333;')).toEqual(['index of refraction 1.333']);
    expect(copiesIn('#define MAX_TAPS 8')).toEqual(['blur taps 8']);
    expect(copiesIn('uniform float uWeights[8];')).toEqual(['blur taps 8']);
    expect(copiesIn('const float GOD_RAY_RANGE = 60.0;')).toEqual(['god-ray range 60']);
    expect(copiesIn('vec3(0.5, 0.3, 0.95)')).toEqual(['band colour 0.5, 0.3, 0.95']);
    // ocean.vert's copies before the steps were injected.
    expect(copiesIn('return band == 0 ? 1 : band == 1 ? 2 : band == 2 ? 3 : band == 3 ? 6 : band == 4 ? 12 : 24;')).toEqual(['band steps', 'band count']);
    expect(copiesIn('const int STEPS[6] = int[6](1, 2, 3, 6, 12, 24);')).toEqual(['band steps']);
    expect(copiesIn('int own = band < 6 ? bandStep(band) : 0;')).toEqual(['band count']);
    expect(copiesIn('if (band < 5) {')).toEqual(['band count']);
  });
});
