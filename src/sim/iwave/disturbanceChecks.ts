import { message, MessageError, type Message } from '../params/message';
import type { Disturbance } from './iwaveGrid';
import { IWAVE_MAX_HEIGHT, IWAVE_MAX_RADIUS, IWAVE_SPACING } from './fieldSize';

export interface DisturbanceOptions {
  /** Metres; raised to one texel if smaller. Default 1. */
  radius?: number;
  /** Metres, negative for a dip. Default 0.3. */
  height?: number;
}

/** How far from the world's origin a stone may fall, metres: the camera's own reach (src/app/camera/cameraPose.ts). */
export const DISTURB_REACH = 1e6;

/**
 * A disturbance checked as the API and the URL take it: a non-finite or out-of-range argument
 * throws a MessageError naming it (its notice in the page's language), and nothing changes; a
 * radius under one texel is raised to one texel, with a notice saying so.
 */
export function checkDisturbance(x: number, z: number, options: DisturbanceOptions = {}): { disturbance: Disturbance; notices: Message[] } {
  const radius = options.radius ?? 1;
  const height = options.height ?? 0.3;
  const fail = (name: string, got: unknown, min: number, max: number, wanted: string): never => {
    throw new MessageError(
      message('disturbInvalid', { name, got: String(got), min, max }),
      `disturb: ${name} must be ${wanted} (got ${String(got)}).`,
    );
  };
  for (const [name, value] of [
    ['x', x],
    ['z', z],
  ] as const) {
    if (!(typeof value === 'number' && Math.abs(value) <= DISTURB_REACH))
      fail(name, value, -DISTURB_REACH, DISTURB_REACH, `a finite number of metres within ±${DISTURB_REACH}`);
  }
  if (!(typeof radius === 'number' && radius > 0 && radius <= IWAVE_MAX_RADIUS))
    fail('radius', radius, 0, IWAVE_MAX_RADIUS, `a number of metres above 0 and at most ${IWAVE_MAX_RADIUS}`);
  if (!(typeof height === 'number' && Math.abs(height) <= IWAVE_MAX_HEIGHT))
    fail('height', height, -IWAVE_MAX_HEIGHT, IWAVE_MAX_HEIGHT, `a number of metres from −${IWAVE_MAX_HEIGHT} to ${IWAVE_MAX_HEIGHT}`);
  const notices: Message[] = [];
  let used = radius;
  if (radius < IWAVE_SPACING) {
    used = IWAVE_SPACING;
    notices.push(message('disturbRadiusRaised', { radius, raised: IWAVE_SPACING }));
  }
  return { disturbance: { x, z, radius: used, height }, notices };
}
