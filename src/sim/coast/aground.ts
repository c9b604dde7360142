import { seaDepth, type SeaFloor } from './bathymetry';

/** How deep the boat's hull reaches under the water line, metres: where the sea is shallower it runs aground. */
export const HULL_DRAFT = 1;

/** Where a boat moving from `from` to `to` stops, and whether it ran aground (sailUntilAground over one floor). */
export type SailLimit = (from: readonly [number, number], to: readonly [number, number]) => { x: number; z: number; stopped: boolean };

/** Whether a boat at world (x, z) would touch the bottom: the still water there is shallower than its draft. */
export function isAground(floor: SeaFloor, x: number, z: number): boolean {
  return seaDepth(floor, x, z) < HULL_DRAFT;
}

/**
 * Where a boat moving from (x0, z0) to (x1, z1) stops: the end point while it stays afloat,
 * otherwise the last of `steps` points along the way before the water gets shallower than the
 * draft. A boat already aground moves only where the water is deeper than where it is. `stopped` says whether it ran aground.
 */
export function sailUntilAground(
  floor: SeaFloor,
  from: readonly [number, number],
  to: readonly [number, number],
  steps = 16,
): { x: number; z: number; stopped: boolean } {
  let last: [number, number] = [from[0], from[1]];
  // A boat already aground may only back off into deeper water.
  if (isAground(floor, from[0], from[1])) {
    const deeper = seaDepth(floor, to[0], to[1]) > seaDepth(floor, from[0], from[1]);
    return deeper ? { x: to[0], z: to[1], stopped: false } : { x: from[0], z: from[1], stopped: true };
  }
  for (let i = 1; i <= steps; i++) {
    const x = from[0] + ((to[0] - from[0]) * i) / steps;
    const z = from[1] + ((to[1] - from[1]) * i) / steps;
    if (isAground(floor, x, z)) return { x: last[0], z: last[1], stopped: true };
    last = [x, z];
  }
  return { x: to[0], z: to[1], stopped: false };
}
