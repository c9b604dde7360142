import type { OceanParams } from '../../params/params';
import { BAND_STEPS, BASE_STEP, LOD_BAND_COLORS, bandStart } from '../../lod/lodBands';
import type { Diagram, DiagramLine, DiagramMark } from './diagram';

/** Where band 0 is drawn from on the log axis: a quarter of L (the axis cannot reach 0). */
const NEAREST = -2;
/** How far the last band is drawn past its start, on the log axis: it reaches the horizon. */
const HORIZON_REACH = 1.6;

/**
 * The distance bands along a line from the camera, distance on a log₂ axis in units of L
 * (each ring doubles the last, so they are evenly spaced on it): where each band starts
 * (bandStart) and its vertex spacing (BAND_STEPS × BASE_STEP), in the LOD debugger's colours.
 */
export function lodDiagram(params: Pick<OceanParams, 'lodDistance' | 'lodBands'>): Diagram {
  const L = params.lodDistance;
  const bands = params.lodBands;
  const at = (distance: number) => (distance > 0 ? Math.log2(distance / L) : NEAREST);
  const lines: DiagramLine[] = [];
  const marks: DiagramMark[] = [];
  for (let b = 0; b < bands; b++) {
    const from = at(bandStart(b, L));
    const to = b + 1 < bands ? at(bandStart(b + 1, L)) : from + HORIZON_REACH;
    lines.push({
      role: 'main',
      points: [
        [from, 0],
        [to, 0],
      ],
      color: LOD_BAND_COLORS[b],
    });
    marks.push({
      id: 'spacing',
      x: (from + to) / 2,
      y: b % 2 === 0 ? 0.55 : 1.05,
      value: BAND_STEPS[b] * BASE_STEP,
      unit: 'm',
      index: b,
      bare: true,
    });
    if (b > 0) marks.push({ id: 'ring', x: from, y: 0, value: bandStart(b, L), unit: 'm', index: b, below: true, centred: true });
  }
  marks.push({ id: 'camera', x: NEAREST, y: 0, value: 0, unit: 'm', below: true });
  const last = at(bandStart(bands - 1, L)) + HORIZON_REACH;
  return {
    kind: 'lodBands',
    x: [NEAREST - 0.3, Math.max(last, 1) + 0.3],
    y: [-1.3, 1.5],
    equalScale: false,
    lines,
    marks,
    headline: bands > 1 ? 'ring' : 'spacing',
  };
}
