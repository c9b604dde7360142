import type { OceanParams, ParamKey } from '../../sim/params/params';
import { compareModelNames } from '../../sim/compare/compareLayout';
import type { TeachingWordId } from '../language/teachingWords';

type WaveModelName = OceanParams['waves'];

/** The parameters only some wave models read, and who reads them. */
const READ_BY: { keys: ParamKey[]; models: WaveModelName[]; reason: TeachingWordId }[] = [
  { keys: ['swellAmplitude', 'swellFrequency', 'rippleStrength', 'rippleBlendSpeed'], models: ['seed'], reason: 'unusedBySpectral' },
  { keys: ['windSpeed', 'windDirection', 'spectrum', 'fetch', 'depth', 'spreading', 'spreadingModel'], models: ['fft', 'gerstner'], reason: 'unusedBySeed' },
  { keys: ['choppiness', 'fftSize', 'foam', 'foamThreshold', 'foamFade', 'foamBreakup', 'normalsCompare'], models: ['fft'], reason: 'unusedByNonFft' },
  { keys: ['gerstnerCount', 'gerstnerSteepness'], models: ['gerstner'], reason: 'unusedByNonGerstner' },
];

/** The models on screen: `waves`, or every model of a side-by-side comparison. */
export function modelsShown(params: Pick<OceanParams, 'waves' | 'compare'>): WaveModelName[] {
  const compared = compareModelNames<WaveModelName>(params.compare);
  return compared.length > 0 ? compared : [params.waves];
}

/**
 * Each parameter no model on screen reads, with the words that say why: the panel and the
 * lesson cards show these disabled, so a control that changes nothing never looks live.
 */
export function unreadParams(params: Pick<OceanParams, 'waves' | 'compare'>): Map<ParamKey, TeachingWordId> {
  const shown = modelsShown(params);
  const unread = new Map<ParamKey, TeachingWordId>();
  for (const group of READ_BY) {
    if (group.models.some((model) => shown.includes(model))) continue;
    for (const key of group.keys) unread.set(key, group.reason);
  }
  return unread;
}
