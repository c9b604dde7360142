import { describe, expect, it } from 'vitest';
import {
  APP_ONLY_PARAMS,
  checkOceanKeys,
  OCEAN_EXTRA_OPTIONS,
  oceanParamKeys,
  oceanParametersOf,
  type OceanParameters,
} from '../../../../src/sim/params/oceanOptionKeys';
import { defaultParams, paramKeys } from '../../../../src/sim/params/params';

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
