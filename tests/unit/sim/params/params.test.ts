import { describe, expect, it } from 'vitest';
import {
  defaultParams,
  paramDefs,
  paramKeys,
  ParamError,
  parseParamText,
  validateParam,
  validateParams,
} from '../../../../src/sim/params/params';
import { isSafeAssetPath, parseUrlState } from '../../../../src/app/url/urlState';
import { Translator } from '../../../../src/app/language/i18n';
import type { Message } from '../../../../src/sim/params/message';

const english = new Translator('en');
const text = (notice: Message | undefined) => (notice ? english.message(notice) : '');

describe('parameter definitions', () => {
  it('give every parameter a default that passes its own validation', () => {
    const defaults = defaultParams();
    for (const key of paramKeys) expect(validateParam(key, defaults[key])).toEqual(defaults[key]);
  });
});

describe('validateParams', () => {
  it('accepts good values', () => {
    expect(validateParams({ swellAmplitude: 2, fresnel: false, waterColor: '#00AAff', seed: 12 })).toEqual({
      swellAmplitude: 2,
      fresnel: false,
      waterColor: '#00aaff',
      seed: 12,
    });
  });

  const bad: [string, unknown, RegExp][] = [
    ['noSuchKey', 1, /Unknown parameter "noSuchKey"/],
    ['swellAmplitude', 1e9, /"swellAmplitude" must lie in \[0, 4\] m/],
    ['swellAmplitude', -1, /"swellAmplitude" must lie in/],
    ['swellAmplitude', Number.NaN, /"swellAmplitude" must be a finite number/],
    ['swellAmplitude', Number.POSITIVE_INFINITY, /must be a finite number/],
    ['swellAmplitude', '2', /"swellAmplitude" must be a finite number, got "2"/],
    ['seed', -1.5, /"seed" must be an integer/],
    ['seed', -1, /"seed" must lie in/],
    ['fresnel', 'yes', /"fresnel" must be true or false/],
    ['waterColor', 'blue', /"waterColor" must be a colour/],
    ['waterColor', 0x123456, /"waterColor" must be a colour/],
  ];
  for (const [key, value, message] of bad) {
    it(`rejects ${key} = ${String(value)} with an error naming it`, () => {
      let error: unknown;
      try {
        validateParams({ [key]: value });
      } catch (e) {
        error = e;
      }
      expect(error).toBeInstanceOf(ParamError);
      expect((error as ParamError).key).toBe(key);
      expect((error as Error).message).toMatch(message);
    });
  }

  it('rejects non-objects', () => {
    expect(() => validateParams(null)).toThrow(ParamError);
    expect(() => validateParams([1])).toThrow(ParamError);
  });
});

describe('URL text', () => {
  it('clamps out-of-range numbers with a notice', () => {
    const parsed = parseParamText('swellAmplitude', '1e9');
    expect(parsed).toMatchObject({ value: paramDefs.swellAmplitude.max, notice: { id: 'paramClamped' } });
    expect(text(parsed.notice)).toBe('"swellAmplitude=1e9" is outside [0, 4] m; clamped to 4.');
  });
  it('falls back to the default for malformed text', () => {
    const seed = parseParamText('seed', '-1.5');
    expect(seed.value).toBe(paramDefs.seed.default);
    expect(text(seed.notice)).toContain('not an integer');
    expect(parseParamText('swellFrequency', 'abc').value).toBe(paramDefs.swellFrequency.default);
    expect(parseParamText('fresnel', 'maybe').value).toBe(true);
  });
  it('reads booleans and colours in their URL forms', () => {
    expect(parseParamText('fresnel', '0')).toEqual({ value: false });
    expect(parseParamText('waterColor', '0A2E45')).toEqual({ value: '#0a2e45' });
  });
});

describe('parseUrlState', () => {
  it('reads seed and a frozen time', () => {
    const state = parseUrlState('?seed=7&t=12.5');
    expect(state.params.seed).toBe(7);
    expect(state.time).toBe(12.5);
    expect(state.notices).toEqual([]);
  });
  it('explains every bad value and falls back safely', () => {
    const state = parseUrlState('?t=abc&seed=-1.5&swellAmplitude=1e9&bogus=1');
    expect(state.time).toBeNull();
    expect(state.params.seed).toBe(paramDefs.seed.default);
    expect(state.params.swellAmplitude).toBe(paramDefs.swellAmplitude.max);
    expect(state.notices).toHaveLength(4);
    const shown = state.notices.map(text).join('\n');
    expect(shown).toMatch(/t=abc/);
    expect(shown).toMatch(/bogus/);
  });
  it('accepts only same-origin sky paths', () => {
    expect(isSafeAssetPath('course/sky')).toBe(true);
    expect(isSafeAssetPath('/assets/sky-2')).toBe(true);
    expect(isSafeAssetPath('https://evil.example/sky')).toBe(false);
    expect(isSafeAssetPath('//evil.example/sky')).toBe(false);
    expect(isSafeAssetPath('../../etc')).toBe(false);
    expect(isSafeAssetPath('javascript:alert(1)')).toBe(false);
    expect(parseUrlState('?sky=https://evil.example/x').sky).toBeNull();
  });
  it('reads a same-origin boat model path and refuses others with a notice', () => {
    expect(parseUrlState('?boat=models/other.glb').boat).toBe('models/other.glb');
    expect(parseUrlState('').boat).toBeNull();
    const refused = parseUrlState('?boat=//evil.example/boat.glb');
    expect(refused.boat).toBeNull();
    expect(refused.notices).toEqual([{ id: 'boatPathInvalid', values: { text: '//evil.example/boat.glb' } }]);
    expect(new Translator('en').message(refused.notices[0])).toMatch(/"boat=\/\/evil\.example\/boat\.glb" is not a path on this site/);
  });
});

describe('choice parameters', () => {
  it('accept only their options, from the API and from the URL', () => {
    expect(validateParams({ shading: 'normals', view: 'heightmap', normals: 'flat' })).toEqual({
      shading: 'normals',
      view: 'heightmap',
      normals: 'flat',
    });
    expect(() => validateParams({ shading: 'toon' })).toThrow(/"shading" must be one of water, normals/);
    expect(parseParamText('view', 'heightmap')).toEqual({ value: 'heightmap' });
    expect(parseParamText('view', 'x-ray')).toMatchObject({ value: 'ocean', notice: { id: 'paramNotChoice', values: { text: 'x-ray' } } });
  });
});
