import { describe, expect, it } from 'vitest';
import {
  APP_ONLY_PARAMS,
  checkOceanKeys,
  defaultOceanOptions,
  OCEAN_EXTRA_OPTIONS,
  oceanOptionDefs,
  oceanParamKeys,
  oceanParametersOf,
  validateOceanOptions,
  type OceanParameters,
} from '../../../../src/sim/params/oceanOptionKeys';
import { defaultParams, paramDefs, paramKeys } from '../../../../src/sim/params/params';
import { ENGLISH_PARAM_LABELS } from '../../../../src/sim/params/englishParamLabels';

/** Compiled by `tsc --noEmit`: each marked line must be a type error, or the compile fails. */
export const typeChecks: Partial<OceanParameters>[] = [
  { waves: 'fft', windSpeed: 12 },
  // @ts-expect-error boatSpeed is the app's boat, not an Ocean option
  { boatSpeed: 3 },
  // @ts-expect-error compare is the app's side-by-side view
  { compare: 'off' },
  // @ts-expect-error exposure is the app's renderer's
  { exposure: 1 },
];

describe('the keys an Ocean reads', () => {
  it('are the parameters less the app-only ones, each app-only key being a parameter', () => {
    expect(APP_ONLY_PARAMS.every((key) => paramKeys.includes(key))).toBe(true);
    expect(oceanParamKeys.length + APP_ONLY_PARAMS.length).toBe(paramKeys.length);
    expect(Object.keys(oceanParametersOf(defaultParams())).sort()).toEqual([...oceanParamKeys].sort());
  });

  it('lets the keys it reads and the named extras through', () => {
    expect(() => checkOceanKeys({ waves: 'fft', windSpeed: 12, sky: null }, ['sky'], 'new Ocean')).not.toThrow();
    expect(() => checkOceanKeys({ sky: null, autoUpdate: true }, OCEAN_EXTRA_OPTIONS, 'new Ocean')).not.toThrow();
  });

  it('throws naming an app-only key, an unknown key, or an extra where none is allowed', () => {
    expect(() => checkOceanKeys({ windSpeed: 12, boatSpeed: 3 }, ['sky'], 'new Ocean')).toThrow(
      /^new Ocean: "boatSpeed" is not an Ocean option but the app's/,
    );
    expect(() => checkOceanKeys({ compare: 'off' }, [], 'Ocean.setParams')).toThrow(/^Ocean\.setParams: "compare" is not an Ocean option/);
    expect(() => checkOceanKeys({ seaLevel: -1 }, ['sky'], 'new Ocean')).toThrow(
      /"seaLevel" is not an Ocean option\. Its options: waves, .*, sky\.$/,
    );
    expect(() => checkOceanKeys({ sky: null }, [], 'Ocean.setParams')).toThrow(/"sky"/);
  });
});

describe("what the library exports of the options: only an Ocean's, with the app's defaults and definitions", () => {
  it('defaultOceanOptions and oceanOptionDefs: every Ocean option at its parameter default, no app-only key', () => {
    const defaults = defaultOceanOptions();
    expect(Object.keys(defaults).sort()).toEqual([...oceanParamKeys].sort());
    expect(Object.keys(oceanOptionDefs).sort()).toEqual([...oceanParamKeys].sort());
    for (const key of oceanParamKeys) {
      expect(defaults[key]).toBe(defaultParams()[key]);
      expect(oceanOptionDefs[key]).toEqual({ ...paramDefs[key], label: ENGLISH_PARAM_LABELS[key] });
      expect(oceanOptionDefs[key].label.length).toBeGreaterThan(2);
    }
    // Control: the app's keys are in the parameters, so the filter did something.
    for (const key of APP_ONLY_PARAMS) {
      expect(key in defaultParams()).toBe(true);
      expect(key in defaults || key in oceanOptionDefs).toBe(false);
    }
  });

  it('validateOceanOptions passes good options, and throws on a bad value, an unknown key or an app-only key', () => {
    expect(validateOceanOptions({ waves: 'fft', windSpeed: 12, waterColor: '12AB9F' })).toEqual({
      waves: 'fft',
      windSpeed: 12,
      waterColor: '#12ab9f',
    });
    expect(() => validateOceanOptions({ windSpeed: 99 })).toThrow(/"windSpeed" must lie in \[1, 30\] m\/s, got 99/);
    expect(() => validateOceanOptions({ seaLevel: -1 })).toThrow(/Unknown parameter "seaLevel"/);
    expect(() => validateOceanOptions({ timeScale: '0.5' })).toThrow(
      /^validateOceanOptions: "timeScale" is not an Ocean option but the app's/,
    );
    expect(() => validateOceanOptions('windSpeed=12')).toThrow(/must be an object/);
  });
});
