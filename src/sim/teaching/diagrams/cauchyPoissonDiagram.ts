import { crestRadii, STATIONARY_PHASE_FROM, stoneGuideReach } from '../../iwave/cauchyPoissonRings';
import { GRAVITY } from '../../wake/kelvinWake';
import { sampled, type Diagram, type DiagramMark } from './diagram';

/** Crests labelled with their radius, outermost first: further in they crowd. */
const LABELLED_CRESTS = 3;

/**
 * A stone's waves `age` seconds after it fell, along a radius: the stationary-phase profile's
 * crests cos(g t²/(4r)) (drawn where the waves are no shorter than the field carries) and the
 * crests r_n = g t²/(8πn) the guide rings on the sea stand at (crestRadii). The long waves
 * lead: the outermost crest is n = 2, and the crests crowd in towards the stone.
 */
export function cauchyPoissonDiagram(age: number): Diagram {
  const reach = stoneGuideReach();
  const radii = crestRadii(age, reach);
  const t2 = age * age;
  // The local wavenumber g t²/(4r²) reaches kMax at r = t √(g / (4 kMax)).
  const inner = age > 0 ? Math.min(reach.maxRadius, age * Math.sqrt(GRAVITY / (4 * reach.kMax))) : reach.maxRadius;
  // Outward of where the phase g t²/(4r) falls below crestRadii's stationary-phase limit the formula does not hold: not drawn.
  const outer = Math.min(reach.maxRadius, (GRAVITY * t2) / (4 * STATIONARY_PHASE_FROM));
  const profile = outer > inner ? sampled(inner, outer, 600, (r) => [r, Math.cos((GRAVITY * t2) / (4 * r))]) : [];
  const marks: DiagramMark[] = radii.map((r, index) => ({
    id: 'crest',
    x: r,
    y: 1,
    value: r,
    unit: 'm',
    index,
    quiet: index >= LABELLED_CRESTS,
  }));
  marks.push({ id: 'age', x: 0.02 * reach.maxRadius, y: -1.45, value: age, unit: 's', bare: true });
  return {
    kind: 'cauchyPoisson',
    x: [0, reach.maxRadius],
    y: [-1.7, 1.7],
    equalScale: false,
    lines: [
      {
        role: 'faint',
        points: [
          [0, 0],
          [reach.maxRadius, 0],
        ],
      },
      ...(profile.length ? [{ role: 'main' as const, points: profile }] : []),
    ],
    marks,
    headline: 'age',
  };
}
