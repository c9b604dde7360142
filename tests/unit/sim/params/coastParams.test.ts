import { describe, expect, it } from 'vitest';
import { defaultParams, paramDefs, parseParamText, ParamError, validateParams } from '../../../../src/sim/params/params';
import { BATHYMETRIES } from '../../../../src/sim/coast/bathymetry';
import { parseUrlState } from '../../../../src/app/url/urlState';
import { oceanParamKeys } from '../../../../src/sim/params/oceanOptionKeys';

describe('the coast parameters', () => {
  it('default to the open sea, a 1.5 m 10 s swell heading for the shore, on a 1:50 slope, with the wind sea on', () => {
    const p = defaultParams();
    expect([p.bathymetry, p.beachSlope, p.swellHeight, p.swellPeriod, p.swellDirection, p.windSea]).toEqual([
      'deep',
      0.02,
      1.5,
      10,
      0,
      true,
    ]);
  });

  it('offer exactly the sea floors the coast knows', () => {
    expect(paramDefs.bathymetry.options).toEqual(BATHYMETRIES);
  });

  it('hold the ranges the brief asks for', () => {
    expect([paramDefs.beachSlope.min, paramDefs.beachSlope.max]).toEqual([0.005, 0.1]);
    expect([paramDefs.swellHeight.min, paramDefs.swellHeight.max]).toEqual([0, 6]);
    expect([paramDefs.swellPeriod.min, paramDefs.swellPeriod.max]).toEqual([4, 20]);
    expect([paramDefs.swellDirection.min, paramDefs.swellDirection.max]).toEqual([-60, 60]);
  });

  it('reach the library Ocean (they are its options, not only the app s)', () => {
    for (const key of ['bathymetry', 'beachSlope', 'swellHeight', 'swellPeriod', 'swellDirection', 'windSea'] as const)
      expect(oceanParamKeys).toContain(key);
  });

  it('reject a bad value through the API, naming it, and change nothing', () => {
    expect(() => validateParams({ bathymetry: 'reef' })).toThrow(ParamError);
    expect(() => validateParams({ beachSlope: 0.5 })).toThrow(/beachSlope/);
    expect(() => validateParams({ swellPeriod: 2 })).toThrow(/swellPeriod/);
    expect(validateParams({ bathymetry: 'island', windSea: false })).toEqual({ bathymetry: 'island', windSea: false });
  });

  it('give a notice for a bad URL value and fall back to the default (a good one passes silently)', () => {
    const bad = parseParamText('bathymetry', 'reef');
    expect(bad.value).toBe('deep');
    expect(bad.notice?.id).toBe('paramNotChoice');
    expect(parseParamText('bathymetry', 'beach')).toEqual({ value: 'beach' });
    const clamped = parseParamText('swellHeight', '9');
    expect(clamped.value).toBe(6);
    expect(clamped.notice?.id).toBe('paramClamped');
  });

  it('come in from the URL with the beach and island presets', () => {
    expect(parseUrlState('?preset=beach').params.bathymetry).toBe('beach');
    expect(parseUrlState('?preset=island').params.bathymetry).toBe('island');
    expect(parseUrlState('?preset=beach&bathymetry=deep').params.bathymetry).toBe('deep');
  });
});
