import { describe, expect, it } from 'vitest';
import { terrainBreaks } from '../../../../src/sim/coast/coastTerrain';

describe("the land's profile", () => {
  it('puts vertices where the ground bends: inland edge, top of the slope, shoreline, deepest part drawn', () => {
    const breaks = terrainBreaks(0.02, 4, 30_000, 4);
    expect(breaks).toEqual([-30_000, -200, -100, 0, 100, 200]);
  });

  it('leaves out a top that lies beyond the inland edge (a low island never reaches its full height)', () => {
    const breaks = terrainBreaks(0.02, 30, 120, 4);
    expect(breaks[0]).toBe(-120);
    expect(breaks).not.toContain(-1500);
  });
});
