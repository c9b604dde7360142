import type { OceanParams, ParamKey } from './params';

/** Whether any of `keys` differs between two parameter sets; everything counts as changed when there is no `before`. */
export function paramsChanged(before: Readonly<OceanParams> | null, after: Readonly<OceanParams>, keys: readonly ParamKey[]): boolean {
  return before === null || keys.some((key) => !Object.is(before[key], after[key]));
}
