import type { OceanParams } from '../../params/params';
import { KELVIN_HALF_ANGLE } from '../../wake/kelvinGuide';
import { transverseWavelength } from '../../wake/transverseWavelength';
import { DEGREE, sampled, type Diagram, type DiagramLine, type DiagramMark } from './diagram';

/** Crests drawn behind the boat. */
const CRESTS = 4;
/** Below this speed (m/s) the boat is taken to be at rest: no wake to draw. */
const AT_REST = 0.05;

/**
 * The wake seen from above, the boat at the origin heading to +x: the ±19.47° wedge
 * (KELVIN_HALF_ANGLE, the guide drawn on the sea) and Kelvin's crest lines for a point
 * source, x = −a cos ψ (1 + sin²ψ), y = a cos²ψ sin ψ with a = n λ, λ = 2πU²/g: where ψ = 0
 * they are the transverse waves, and they fold back at the wedge's cusps.
 */
export function kelvinDiagram(params: Pick<OceanParams, 'boatSpeed'>): Diagram {
  const speed = Math.abs(params.boatSpeed);
  const moving = speed >= AT_REST;
  const wavelength = transverseWavelength(speed);
  const reach = moving ? (CRESTS + 0.6) * wavelength : 10;
  const lines: DiagramLine[] = [];
  for (const side of [-1, 1]) {
    lines.push({
      role: 'second',
      points: [
        [0, 0],
        [-reach * Math.cos(KELVIN_HALF_ANGLE), side * reach * Math.sin(KELVIN_HALF_ANGLE)],
      ],
    });
  }
  if (moving) {
    for (let n = 1; n <= CRESTS; n++) {
      const a = n * wavelength;
      lines.push({
        role: 'main',
        points: sampled(-Math.PI / 2, Math.PI / 2, 90, (psi) => [
          -a * Math.cos(psi) * (1 + Math.sin(psi) ** 2),
          a * Math.cos(psi) ** 2 * Math.sin(psi),
        ]),
      });
    }
  }
  const half = reach * Math.sin(KELVIN_HALF_ANGLE) * 1.25;
  const marks: DiagramMark[] = [
    {
      id: 'angle',
      x: -0.55 * reach,
      y: 0.55 * reach * Math.tan(KELVIN_HALF_ANGLE) * 0.5,
      value: KELVIN_HALF_ANGLE / DEGREE,
      unit: '°',
      bare: true,
    },
    // The boat is a dot at the apex; its speed is written in the corner below it, clear of the crests.
    { id: 'boat', x: 0, y: 0, value: params.boatSpeed, unit: 'm/s', quiet: true },
    { id: 'boat', x: 0.1 * reach, y: -0.85 * half, value: params.boatSpeed, unit: 'm/s', bare: true },
  ];
  if (moving) marks.push({ id: 'transverse', x: -wavelength, y: 0, value: wavelength, unit: 'm', below: true, centred: true });
  return { kind: 'kelvin', x: [-reach * 1.02, reach * 0.12], y: [-half, half], equalScale: true, lines, marks, headline: 'angle' };
}
