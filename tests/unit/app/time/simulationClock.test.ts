import { describe, expect, it } from 'vitest';
import { SimulationClock } from '../../../../src/app/time/simulationClock';

describe('the simulation clock', () => {
  it('plays at the time scale, caps a long frame, and a step is one 1/60 s frame at the scale, paused or not', () => {
    const clock = new SimulationClock(2, true);
    clock.advance(0.02, 0.25);
    expect(clock.time).toBeCloseTo(2.005, 12);
    clock.advance(5, 0.5);
    expect(clock.time).toBeCloseTo(2.005 + SimulationClock.MAX_STEP * 0.5, 12);
    clock.playing = false;
    clock.advance(0.02, 1);
    const paused = clock.time;
    expect(paused).toBeCloseTo(2.055, 12);
    clock.step(0.1);
    expect(clock.time).toBeCloseTo(paused + 0.1 / 60, 12);
    // Control: a step that ignored the scale would have moved ten times as far.
    expect(Math.abs(clock.time - (paused + 1 / 60))).toBeGreaterThan(1e-3);
  });
});
