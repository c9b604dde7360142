import type { OceanParams, ParamKey } from '../../sim/params/params';
import { compareModelNames } from '../../sim/compare/compareLayout';
import type { TeachingWordId } from '../language/teachingWords';

type WaveModelName = OceanParams['waves'];

/** The parameters only some wave models read, and who reads them. */
const READ_BY: { keys: ParamKey[]; models: WaveModelName[]; reason: TeachingWordId }[] = [
  { keys: ['swellAmplitude', 'swellFrequency', 'rippleStrength', 'rippleBlendSpeed'], models: ['seed'], reason: 'unusedBySpectral' },
  {
    keys: ['windSpeed', 'windDirection', 'spectrum', 'fetch', 'depth', 'spreading', 'spreadingModel'],
    models: ['fft', 'gerstner'],
    reason: 'unusedBySeed',
  },
  {
    keys: ['choppiness', 'fftSize', 'foam', 'foamThreshold', 'foamFade', 'waveGroups', 'windrows', 'normalsCompare'],
    models: ['fft'],
    reason: 'unusedByNonFft',
  },
  { keys: ['gerstnerCount', 'gerstnerSteepness'], models: ['gerstner'], reason: 'unusedByNonGerstner' },
];

/** The parameters read only while a switch is on: a foam bias with no foam, the sky's blur on a mirror. */
const READ_WHILE_ON: { keys: ParamKey[]; switchKey: SwitchKey; reason: TeachingWordId }[] = [
  { keys: ['foamThreshold', 'foamFade', 'waveGroups', 'windrows'], switchKey: 'foam', reason: 'unusedWithoutFoam' },
  { keys: ['skyBlur'], switchKey: 'seaRoughness', reason: 'unusedWithoutRoughness' },
  { keys: ['waterColor'], switchKey: 'waterColorPicked', reason: 'unusedWithoutPickedColor' },
  { keys: ['causticsIntensity'], switchKey: 'caustics', reason: 'unusedWithoutCaustics' },
  { keys: ['godRaysIntensity'], switchKey: 'godRays', reason: 'unusedWithoutGodRays' },
];
type SwitchKey = 'foam' | 'seaRoughness' | 'waterColorPicked' | 'caustics' | 'godRays';

/** The models on screen: `waves`, or every model of a side-by-side comparison. */
export function modelsShown(params: Pick<OceanParams, 'waves' | 'compare'>): WaveModelName[] {
  const compared = compareModelNames<WaveModelName>(params.compare);
  return compared.length > 0 ? compared : [params.waves];
}

/**
 * Each parameter nothing on screen reads, with the words that say why: no model on screen
 * reads it, or its switch is off (a switch left out counts as on). The panel and the lesson
 * cards show these disabled, so a control that changes nothing never looks live.
 */
export function unreadParams(
  params: Pick<OceanParams, 'waves' | 'compare'> & Partial<Pick<OceanParams, SwitchKey>>,
): Map<ParamKey, TeachingWordId> {
  const shown = modelsShown(params);
  const unread = new Map<ParamKey, TeachingWordId>();
  for (const group of READ_BY) {
    if (group.models.some((model) => shown.includes(model))) continue;
    for (const key of group.keys) unread.set(key, group.reason);
  }
  for (const group of READ_WHILE_ON) {
    if (params[group.switchKey] !== false) continue;
    for (const key of group.keys) if (!unread.has(key)) unread.set(key, group.reason);
  }
  return unread;
}
