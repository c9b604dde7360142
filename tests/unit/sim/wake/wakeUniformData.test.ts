import { describe, expect, it } from 'vitest';
import { wakeHeight } from '../../../../src/sim/wake/kelvinWake';
import { WakeTrack } from '../../../../src/sim/wake/wakeTrack';
import { packWakeUniforms, wakeAtWorld } from '../../../../src/sim/wake/wakeUniformData';

const PARAMS = { strength: 1, hullLength: 8 };

/** A boat 1.9 km out sailing along +x at 4 m/s for 100 s, a million seconds into the session. */
// Neither the times nor the positions fall on float32's lattice (1/16 s and 1/8192 m steps there).
const T0 = 999_999.97;
const X0 = 1700.37;
function farTrack(): { track: WakeTrack; time: number; head: [number, number] } {
  const track = new WakeTrack();
  const frames = 3000;
  for (let i = 0; i <= frames; i++) track.record(T0 + i / 30, X0 + (4 * i) / 30, -1900.011, 4);
  return { track, time: T0 + frames / 30, head: [X0 + (4 * frames) / 30, -1900.011] };
}

describe('packWakeUniforms / wakeAtWorld', () => {
  const { track, time, head } = farTrack();
  const data = packWakeUniforms(track.points(), time, PARAMS, 2.6);

  // Measured: 1.1e-6 m apart at most (float32 rounding of the track, relative to the boat).
  it('packs the track relative to the boat so float32 loses nothing that matters 1.9 km out', () => {
    expect(data.origin).toEqual(head.map(Math.fround));
    expect(data.count).toBe(64);
    let worst = 0;
    for (const [dx, dz] of [
      [-30, 5],
      [-60, -12],
      [-45, 0],
      [-120, 30],
      [-8, 2],
    ]) {
      const exact = wakeHeight(head[0] + dx, head[1] + dz, time, track.points(), PARAMS);
      worst = Math.max(worst, Math.abs(wakeAtWorld(head[0] + dx, head[1] + dz, data, PARAMS)[0] - exact));
    }
    if (process.env.WAKE_REPORT) console.log(`packed: ${worst}`);
    expect(worst).toBeLessThan(1e-5);
  });

  // Measured: 0.027 m off. Float32 has 1/16 s steps at 10⁶ s, so ages are taken in float64.
  it('would lose the wake to float32 if absolute times were uploaded instead of ages (negative control)', () => {
    const world = track.points().map((p) => ({ ...p, time: Math.fround(p.time) }));
    let worst = 0;
    for (const [dx, dz] of [
      [-30, 5],
      [-60, -12],
      [-45, 0],
      [-120, 30],
      [-8, 2],
    ]) {
      const exact = wakeHeight(head[0] + dx, head[1] + dz, time, track.points(), PARAMS);
      worst = Math.max(worst, Math.abs(wakeHeight(head[0] + dx, head[1] + dz, Math.fround(time), world, PARAMS) - exact));
    }
    if (process.env.WAKE_REPORT) console.log(`float32 absolute times: ${worst}`);
    expect(worst).toBeGreaterThan(1e-3);
  });

  it('is zero beyond the radius and with the strength at zero', () => {
    const r = data.params[2];
    expect(r).toBeGreaterThan(100);
    expect(wakeAtWorld(head[0] - r - 1, head[1], data, PARAMS)).toEqual([0, 0, 0]);
    const off = packWakeUniforms(track.points(), time, { ...PARAMS, strength: 0 }, 2.6);
    expect(off.count).toBe(0);
    expect(wakeAtWorld(head[0] - 30, head[1], off, PARAMS)).toEqual([0, 0, 0]);
  });
});
