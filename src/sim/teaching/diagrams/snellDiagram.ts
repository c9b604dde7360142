import { WATER_IOR, AIR_IOR } from '../../optics/fresnel';
import { refractDirection, snellWindowHalfAngle } from '../../underwater/snellWindow';
import { DEGREE, type Diagram, type DiagramLine } from './diagram';

/** Angles from the vertical of the rays drawn from the eye, degrees. */
const RAY_ANGLES = [0, 20, 35, 60, 75];

/**
 * An eye one metre under a flat surface looking up: rays inside the critical angle leave
 * into the air, bent away from the normal (refractDirection, as the shader does); the ray at
 * the critical angle grazes the surface, the window's edge; those beyond are reflected back
 * down. The window's radius on the surface is tan θc.
 */
export function snellDiagram(nWater = WATER_IOR, nAir = AIR_IOR): Diagram {
  const critical = snellWindowHalfAngle(nWater, nAir);
  const lines: DiagramLine[] = [
    {
      role: 'faint',
      points: [
        [-3, 0],
        [3, 0],
      ],
    },
  ];
  const eye: [number, number] = [0, -1];
  const rays = [...RAY_ANGLES.map((a) => a * DEGREE), critical].sort((a, b) => a - b);
  for (const angle of rays) {
    for (const side of [-1, 1]) {
      const hit: [number, number] = [side * Math.tan(angle), 0];
      const direction: [number, number, number] = [side * Math.sin(angle), Math.cos(angle), 0];
      const out = refractDirection(direction, [0, -1, 0], nWater / nAir);
      const edge = angle === critical;
      if (out && !edge) {
        const reach = 1.2 / Math.max(0.2, Math.hypot(out[0], out[1]));
        lines.push({ role: 'main', points: [eye, hit, [hit[0] + out[0] * reach, out[1] * reach]] });
      } else if (edge) {
        lines.push({ role: 'second', points: [eye, hit, [hit[0] + side * 0.9, 0]] });
      } else {
        lines.push({ role: 'guide', points: [eye, hit, [hit[0] + side * Math.tan(angle) * 0.8, -0.8]] });
      }
    }
  }
  return {
    kind: 'snell',
    x: [-3, 3],
    y: [-1.25, 1.25],
    equalScale: true,
    lines,
    marks: [
      { id: 'critical', x: Math.tan(critical) * 0.45, y: -0.55, value: critical / DEGREE, unit: '°' },
      { id: 'window', x: Math.tan(critical), y: 0, value: Math.tan(critical), unit: 'm' },
      { id: 'eye', x: 0, y: -1, value: 1, unit: 'm' },
    ],
    headline: 'critical',
  };
}
