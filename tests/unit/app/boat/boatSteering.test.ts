import { describe, expect, it } from 'vitest';
import { defaultParams, type OceanParams } from '../../../../src/sim/params/params';
import { BoatSteering, onStep } from '../../../../src/app/boat/boatSteering';

/** A key event as the browser sends it, for node's EventTarget (no KeyboardEvent there). */
function key(type: 'keydown' | 'keyup', code: string): Event {
  return Object.assign(new Event(type, { cancelable: true }), { code });
}

function steer(codes: string[], frames: number, start: Partial<OceanParams> = {}): { stored: OceanParams[]; params: OceanParams } {
  const target = new EventTarget();
  let params = { ...defaultParams(), ...start };
  const stored: OceanParams[] = [];
  const steering = new BoatSteering(
    target as unknown as HTMLElement,
    (change) => {
      params = { ...params, ...change };
      stored.push(params);
    },
    () => params,
  );
  for (const code of codes) target.dispatchEvent(key('keydown', code));
  // 60 Hz frames, the step the loop hands over, with the jitter of a real one.
  for (let i = 0; i < frames; i++) steering.apply(1 / 60 + (i % 3) * 1e-4);
  steering.dispose();
  return { stored, params };
}

// So the panel and a shared link show 2.4, not 2.4335999999999984.
describe("keyboard steering stores values on the parameters' steps", () => {
  it('holding W for 2 s gives speeds of one decimal, reaching 4 m/s', () => {
    const { stored, params } = steer(['KeyW'], 120);
    expect(stored.length).toBeGreaterThan(100);
    for (const p of stored) expect(String(p.boatSpeed)).toMatch(/^-?\d+(\.\d)?$/);
    expect(params.boatSpeed).toBeCloseTo(4, 1);
  });

  it('holding D for 1 s gives whole-degree headings, turning 45°', () => {
    const { stored, params } = steer(['KeyD'], 60);
    for (const p of stored) expect(Number.isInteger(p.boatHeading)).toBe(true);
    expect(params.boatHeading).toBeGreaterThanOrEqual(334);
    expect(params.boatHeading).toBeLessThanOrEqual(336);
  });

  it('boatTurnRate turns the boat as a held key would: 6 °/s for 5 s is 30°, to starboard; none without it (control)', () => {
    const { params } = steer([], 300, { boatTurnRate: 6 });
    expect(params.boatHeading).toBeGreaterThanOrEqual(319);
    expect(params.boatHeading).toBeLessThanOrEqual(321);
    expect(steer([], 300, { boatTurnRate: -6 }).params.boatHeading).toBe(260);
    expect(steer([], 300).stored).toEqual([]);
  });

  it("rounds to the step with the step's decimals", () => {
    expect(onStep(2.4335999999999984, 0.1)).toBe(2.4);
    expect(onStep(0.15000000000000002, 0.05)).toBe(0.15);
    expect(onStep(359.6, 1)).toBe(360);
    expect(String(onStep(0.30000000000000004, 0.1))).toBe('0.3');
  });
});
