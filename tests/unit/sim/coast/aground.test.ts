import { describe, expect, it } from 'vitest';
import { HULL_DRAFT, isAground, sailUntilAground } from '../../../../src/sim/coast/aground';
import { BEACH_SHORE_X, seaDepth, type SeaFloor } from '../../../../src/sim/coast/bathymetry';
import { BoatMotion } from '../../../../src/sim/boat/boatMotion';

const beach: SeaFloor = { bathymetry: 'beach', beachSlope: 0.02, deepDepth: 1000 };
/** Where the beach's water is exactly the hull's draft deep. */
const DRAFT_LINE_X = BEACH_SHORE_X - HULL_DRAFT / beach.beachSlope;

describe('running aground', () => {
  it('happens where the still water is shallower than the draft, and never on the open sea', () => {
    expect(isAground(beach, DRAFT_LINE_X - 1, 0)).toBe(false);
    expect(isAground(beach, DRAFT_LINE_X + 1, 0)).toBe(true);
    expect(isAground(beach, BEACH_SHORE_X + 50, 0)).toBe(true);
    expect(isAground({ ...beach, bathymetry: 'deep' }, BEACH_SHORE_X + 50, 0)).toBe(false);
  });

  it('stops a boat heading for the shore before the draft line, and says so', () => {
    const stop = sailUntilAground(beach, [DRAFT_LINE_X - 10, 5], [DRAFT_LINE_X + 10, 5]);
    expect(stop.stopped).toBe(true);
    expect(stop.x).toBeLessThanOrEqual(DRAFT_LINE_X);
    expect(stop.x).toBeGreaterThan(DRAFT_LINE_X - 2);
    expect(seaDepth(beach, stop.x, stop.z)).toBeGreaterThanOrEqual(HULL_DRAFT);
  });

  it('lets a boat sail along the shore in deep enough water, and back off the shore once aground', () => {
    expect(sailUntilAground(beach, [0, 0], [0, 40])).toEqual({ x: 0, z: 40, stopped: false });
    const aground: [number, number] = [DRAFT_LINE_X + 5, 0];
    expect(sailUntilAground(beach, aground, [aground[0] - 3, 0]).stopped).toBe(false);
    expect(sailUntilAground(beach, aground, [aground[0] + 3, 0])).toEqual({ x: aground[0], z: 0, stopped: true });
  });

  it('keeps the boat afloat in BoatMotion: at full speed towards the beach it ends short of the draft line', () => {
    const motion = new BoatMotion([DRAFT_LINE_X - 30, 0]);
    motion.limit = (from, to) => sailUntilAground(beach, from, to);
    // Heading 90°: towards +x (clockwise from −z, src/sim/boat/boatPose.ts).
    const controls = { heading: Math.PI / 2, speed: 12, response: 0.25 };
    const hull = { length: 8, beam: 2.6 };
    for (let t = 0; t <= 10; t += 0.1) motion.update(t, controls, hull, () => 0);
    const { pose } = motion.state()!;
    expect(motion.aground).toBe(true);
    expect(pose.x).toBeLessThan(DRAFT_LINE_X);
    expect(pose.x).toBeGreaterThan(DRAFT_LINE_X - 12 * 0.1 - 1);
  });

  it('negative control: without the limit the same boat sails up the beach', () => {
    const motion = new BoatMotion([DRAFT_LINE_X - 30, 0]);
    const controls = { heading: Math.PI / 2, speed: 12, response: 0.25 };
    for (let t = 0; t <= 10; t += 0.1) motion.update(t, controls, { length: 8, beam: 2.6 }, () => 0);
    expect(motion.state()!.pose.x).toBeGreaterThan(BEACH_SHORE_X);
    expect(motion.aground).toBe(false);
  });
});
