import { ENGLISH_PARAM_LABELS } from './englishParamLabels';
import { defaultParams, isParamKey, paramDefs, paramKeys, validateParams, type OceanParams, type ParamKey } from './params';

/**
 * The parameters only the app reads: its boat and wake, clock, camera, panels, teaching views
 * and side-by-side models (an Ocean draws one model: `waves`). The library's `Ocean` never
 * looks at them, so a user who passes one is told so instead of being ignored.
 */
export const APP_ONLY_PARAMS = [
  'compare',
  'compareSplit',
  'exposure',
  'boatSpeed',
  'boatHeading',
  'boatResponse',
  'boatFollow',
  'boatTurnRate',
  'wake',
  'wakeStrength',
  'wakeGuide',
  'view',
  'fresnelPlot',
  'timeScale',
  'physics',
] as const satisfies readonly ParamKey[];

export type AppOnlyParamKey = (typeof APP_ONLY_PARAMS)[number];
/** The parameters an `Ocean` reads. */
export type OceanParamKey = Exclude<ParamKey, AppOnlyParamKey>;
export type OceanParameters = Pick<OceanParams, OceanParamKey>;

/** The options of an Ocean that are not parameters: the sky it reflects, and whether it updates itself for each camera. */
export const OCEAN_EXTRA_OPTIONS = ['sky', 'autoUpdate'] as const;

const isAppOnly = (key: string): boolean => (APP_ONLY_PARAMS as readonly string[]).includes(key);

export const oceanParamKeys: readonly OceanParamKey[] = paramKeys.filter((key): key is OceanParamKey => !isAppOnly(key));

/** `params` with only the keys an Ocean reads. */
export function oceanParametersOf(params: OceanParams): OceanParameters {
  return Object.fromEntries(oceanParamKeys.map((key) => [key, params[key]])) as OceanParameters;
}

/**
 * Every option of an Ocean at its default: what `new Ocean(renderer)` starts from, and what
 * `ocean.getParams()` answers until a setParams.
 */
export function defaultOceanOptions(): OceanParameters {
  return oceanParametersOf(defaultParams());
}

/** The definition of each option an Ocean reads (kind, default, range, unit, label): what a panel of your own needs to offer it. */
export const oceanOptionDefs = Object.freeze(
  Object.fromEntries(oceanParamKeys.map((key) => [key, { ...paramDefs[key], label: ENGLISH_PARAM_LABELS[key] }])),
) as Readonly<{ [K in OceanParamKey]: (typeof paramDefs)[K] & { label: string } }>;

/**
 * `options` checked as `new Ocean` and `setParams` check them (from a URL, a form, a saved
 * file): each value against its definition (a ParamError naming the key), then each key an
 * option an Ocean reads (an Error naming an app-only key).
 */
export function validateOceanOptions(options: unknown): Partial<OceanParameters> {
  const valid = validateParams(options);
  checkOceanKeys(valid, [], 'validateOceanOptions');
  return valid as Partial<OceanParameters>;
}

/**
 * Throws an Error naming the first key of `options` that an Ocean does not read: one of the
 * app's parameters (saying whose it is), or a key that is neither a parameter nor one of
 * `extraKeys` (the options that are not parameters, like `sky`). `where` names the call.
 */
export function checkOceanKeys(options: object, extraKeys: readonly string[], where: string): void {
  for (const key of Object.keys(options)) {
    if (!extraKeys.includes(key) && (isAppOnly(key) || !isParamKey(key))) {
      throw new Error(
        `${where}: "${key}" is not an Ocean option${isAppOnly(key) ? " but the app's (boat, clock, panels, views, compare)" : ''}. Its options: ${[...oceanParamKeys, ...extraKeys].join(', ')}.`,
      );
    }
  }
}
