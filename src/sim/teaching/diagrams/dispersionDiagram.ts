import type { OceanParams } from '../../params/params';
import { angularFrequency, groupVelocity, waveNumber } from '../../waves/dispersion';
import { surfaceStateAt } from '../../waves/seed/seedSurface';
import { seaStateFromParams, type SeaParams } from '../../waves/spectra/seaState';
import { frequencySpectrum } from '../../waves/spectra/waveSpectrum';
import { sampled, type Diagram } from './diagram';

type SwellParams = Pick<OceanParams, 'swellAmplitude' | 'swellFrequency' | 'rippleStrength' | 'rippleBlendSpeed'>;

/** Wraps a phase difference into (−π, π]. */
function wrapped(d: number): number {
  return d - 2 * Math.PI * Math.round(d / (2 * Math.PI));
}

/**
 * The seed swell's first product, sin(kx + a t) cos(kz + b t), is two plane waves:
 * ½ sin(k(x + z) + (a + b) t) + ½ sin(k(x − z) + (a − b) t), each of wavenumber √2 k. Their
 * frequencies are read from the phases surfaceStateAt hands the shader, over a short step.
 */
export function seedSwellComponents(params: SwellParams): { k: number; omega: number; speed: number }[] {
  const step = 0.01;
  const before = surfaceStateAt(params, 0).swellPhase;
  const after = surfaceStateAt(params, step).swellPhase;
  const a = wrapped(after[0] - before[0]) / step;
  const b = wrapped(after[1] - before[1]) / step;
  const k = Math.SQRT2 * params.swellFrequency;
  return [a + b, a - b].map((omega) => ({ k, omega, speed: omega / k }));
}

/** ω(k) of deep water beside the seed swell's two components: one runs faster than real waves of its length, one slower. */
export function seedDispersionDiagram(params: SwellParams): Diagram {
  const [sum, difference] = seedSwellComponents(params);
  const kMax = 2.2 * sum.k;
  const curve = sampled(0, kMax, 80, (k) => [k, angularFrequency(k)]);
  const omegaMax = Math.max(angularFrequency(kMax), sum.omega) * 1.1;
  const real = angularFrequency(sum.k);
  return {
    kind: 'seedDispersion',
    x: [0, kMax],
    y: [0, omegaMax],
    equalScale: false,
    lines: [
      { role: 'main', points: curve },
      {
        role: 'guide',
        points: [
          [sum.k, 0],
          [sum.k, omegaMax],
        ],
      },
    ],
    marks: [
      { id: 'sum', x: sum.k, y: sum.omega, value: sum.speed, unit: 'm/s' },
      { id: 'curve', x: sum.k, y: real, value: real / sum.k, unit: 'm/s' },
      { id: 'difference', x: difference.k, y: difference.omega, value: difference.speed, unit: 'm/s' },
    ],
    headline: 'sum',
  };
}

/**
 * ω(k) in deep water and at the sea's depth, the spectral peak on it, its phase speed ω/k
 * (the slope of the line from the origin) and its group speed dω/dk (the tangent's slope).
 */
export function depthDispersionDiagram(params: SeaParams): Diagram {
  const sea = seaStateFromParams(params);
  const omegaPeak = frequencySpectrum(sea).peak;
  const kPeak = waveNumber(omegaPeak, sea.depth);
  const phase = omegaPeak / kPeak;
  const group = groupVelocity(kPeak, sea.depth);
  const kMax = 3 * kPeak;
  const omegaMax = angularFrequency(kMax) * 1.05;
  const lines: Diagram['lines'] = [];
  if (Number.isFinite(sea.depth)) lines.push({ role: 'faint', points: sampled(0, kMax, 80, (k) => [k, angularFrequency(k)]) });
  lines.push(
    { role: 'main', points: sampled(0, kMax, 80, (k) => [k, angularFrequency(k, sea.depth)]) },
    {
      role: 'second',
      points: [
        [0, 0],
        [kMax, phase * kMax],
      ],
    },
    {
      role: 'guide',
      points: [
        [0.3 * kPeak, omegaPeak - 0.7 * kPeak * group],
        [1.8 * kPeak, omegaPeak + 0.8 * kPeak * group],
      ],
    },
  );
  return {
    kind: 'depthDispersion',
    x: [0, kMax],
    y: [0, omegaMax],
    equalScale: false,
    lines,
    marks: [
      { id: 'peak', x: kPeak, y: omegaPeak, value: (2 * Math.PI) / kPeak, unit: 'm' },
      { id: 'phase', x: 0.55 * kPeak, y: 0.55 * omegaPeak, value: phase, unit: 'm/s' },
      { id: 'group', x: 1.8 * kPeak, y: omegaPeak + 0.8 * kPeak * group, value: group, unit: 'm/s' },
    ],
    headline: 'phase',
  };
}
