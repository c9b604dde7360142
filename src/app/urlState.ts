import { defaultParams, isParamKey, parseParamText, type OceanParams } from '../sim/params';

/** URL keys that are not ocean parameters but are understood by the page. */
const PAGE_KEYS = ['t', 'sky', 'camera', 'target'] as const;

export interface UrlState {
  params: OceanParams;
  /** Frozen time in seconds when `t` is given, otherwise null (time runs). */
  time: number | null;
  /** Base path of the six sky images when the page names its own. */
  sky: string | null;
  /** Camera position and orbit target from `camera=x,y,z` and `target=x,y,z`, metres (e.g. camera=0,-6,40 dives). */
  camera: [number, number, number] | null;
  target: [number, number, number] | null;
  notices: string[];
}

/**
 * A sky path must stay on this origin: a relative path or one starting with a single "/",
 * made of ordinary path characters, never climbing out with "..".
 */
export function isSafeAssetPath(path: string): boolean {
  return /^[A-Za-z0-9._~\-/]+$/.test(path) && !path.startsWith('//') && !path.split('/').includes('..');
}

/** Three comma-separated finite numbers of at most 1e6 in size, or null. */
export function parseVector3(text: string): [number, number, number] | null {
  const parts = text.split(',');
  if (parts.length !== 3 || parts.some((p) => p.trim() === '')) return null;
  const numbers = parts.map(Number);
  return numbers.every((n) => Number.isFinite(n) && Math.abs(n) <= 1e6) ? (numbers as [number, number, number]) : null;
}

export function parseUrlState(search: string): UrlState {
  const query = new URLSearchParams(search);
  const params = defaultParams();
  const notices: string[] = [];
  let time: number | null = null;
  let sky: string | null = null;
  const vectors: { camera: [number, number, number] | null; target: [number, number, number] | null } = { camera: null, target: null };

  for (const [key, text] of query) {
    if (key === 't') {
      const value = text.trim() === '' ? NaN : Number(text);
      if (Number.isFinite(value) && value >= 0 && value <= 1e9) time = value;
      else notices.push(`"t=${text}" is not a time in seconds between 0 and 1e9; the animation runs from 0 instead.`);
    } else if (key === 'sky') {
      if (isSafeAssetPath(text)) sky = text;
      else notices.push(`"sky=${text}" is not a path on this site; using the built-in sky.`);
    } else if (key === 'camera' || key === 'target') {
      vectors[key] = parseVector3(text);
      if (!vectors[key]) notices.push(`"${key}=${text}" is not three numbers like 0,-6,40; using the default ${key}.`);
    } else if (isParamKey(key)) {
      const { value, notice } = parseParamText(key, text);
      (params as Record<string, unknown>)[key] = value;
      if (notice) notices.push(notice);
    } else if (!(PAGE_KEYS as readonly string[]).includes(key)) {
      notices.push(`Unknown URL parameter "${key}" was ignored.`);
    }
  }
  return { params, time, sky, ...vectors, notices };
}
