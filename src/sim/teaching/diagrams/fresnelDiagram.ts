import { AIR_IOR, WATER_IOR, fresnelReflectance, schlickReflectance } from '../../optics/fresnel';
import { DEGREE, sampled, type Diagram } from './diagram';

/** Steps of the search for the largest difference, per degree. */
const STEPS_PER_DEGREE = 10;

/** Where Schlick's approximation is furthest from the exact reflectance, light from air into water, and by how much. */
export function largestSchlickError(n1 = AIR_IOR, n2 = WATER_IOR): { angle: number; exact: number; schlick: number } {
  let best = { angle: 0, exact: 0, schlick: 0 };
  for (let i = 0; i <= 90 * STEPS_PER_DEGREE; i++) {
    const angle = i / STEPS_PER_DEGREE;
    const c = Math.cos(angle * DEGREE);
    const exact = fresnelReflectance(c, n1, n2);
    const schlick = schlickReflectance(c, n1, n2);
    if (Math.abs(exact - schlick) > Math.abs(best.exact - best.schlick)) best = { angle, exact, schlick };
  }
  return best;
}

/** Reflectance against the angle from the normal: the exact table the shader reads, Schlick's curve, and where they part most. */
export function fresnelDiagram(n1 = AIR_IOR, n2 = WATER_IOR): Diagram {
  const worst = largestSchlickError(n1, n2);
  const curve = (f: typeof fresnelReflectance) => sampled(0, 90, 180, (a) => [a, f(Math.cos(a * DEGREE), n1, n2)]);
  return {
    kind: 'fresnel',
    x: [0, 90],
    y: [0, 1],
    equalScale: false,
    lines: [
      { role: 'second', points: curve(schlickReflectance) },
      { role: 'main', points: curve(fresnelReflectance) },
      {
        role: 'guide',
        points: [
          [worst.angle, worst.exact],
          [worst.angle, worst.schlick],
        ],
      },
    ],
    marks: [
      { id: 'difference', x: worst.angle, y: Math.max(worst.exact, worst.schlick), value: Math.abs(worst.exact - worst.schlick), unit: '' },
      { id: 'normal', x: 0, y: fresnelReflectance(1, n1, n2), value: fresnelReflectance(1, n1, n2), unit: '' },
    ],
    headline: 'difference',
  };
}
