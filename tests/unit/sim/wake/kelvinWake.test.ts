import { describe, expect, it } from 'vitest';
import {
  GRAVITY,
  froudeNumber,
  wakeHeight,
  wakeHeightAndGradient,
  wakeSources,
  type WakeParams,
  type WakeSource,
} from '../../../../src/sim/wake/kelvinWake';
import { TRACK_POINTS, WakeTrack } from '../../../../src/sim/wake/wakeTrack';

const KELVIN_DEG = (Math.asin(1 / 3) * 180) / Math.PI; // 19.47°
const HULL = 8; // the project's boat, metres
const PARAMS: WakeParams = { strength: 1, hullLength: HULL };
const FRAME = 1 / 30;
/** The arc scans take ≈ 1–2 s alone; the machine's two cores are shared, so room to spare. */
const HEAVY_TIMEOUT = 30_000;

/** Sails a boat at speed U for `duration` seconds from (0, 0) along +x, turning at `turnRate` rad/s, recording every frame. */
function sail(speed: number, duration: number, turnRate = 0): { track: WakeTrack; path: [number, number][]; time: number } {
  const track = new WakeTrack();
  const path: [number, number][] = [];
  let x = 0;
  let z = 0;
  let heading = 0;
  const frames = Math.round(duration / FRAME);
  for (let i = 0; i <= frames; i++) {
    const t = 100 + i * FRAME;
    track.record(t, x, z, speed);
    path.push([x, z]);
    heading += turnRate * FRAME;
    x += speed * Math.cos(heading) * FRAME;
    z += speed * Math.sin(heading) * FRAME;
  }
  return { track, path: path.reverse(), time: 100 + frames * FRAME };
}

/** The wake of a boat at (0, 0) that came along +x (so "behind" is −x), relative to the boat. */
function straightSources(speed: number): WakeSource[] {
  const { track, time } = sail(speed, 200);
  const head = track.points()[0];
  return wakeSources(track.points(), time, head.x, head.z);
}

/** √2 × the RMS of η over one wavelength of radius around R, at angle `deg` off the track behind the boat: the local envelope. */
function envelope(sources: WakeSource[], params: WakeParams, radius: number, wavelength: number, deg: number): number {
  const a = (deg * Math.PI) / 180;
  let sum = 0;
  const n = 32;
  for (let i = 0; i < n; i++) {
    const r = radius - wavelength / 2 + (wavelength * (i + 0.5)) / n;
    const h = wakeHeightAndGradient(-r * Math.cos(a), r * Math.sin(a), sources, params)[0];
    sum += h * h;
  }
  return Math.sqrt((2 * sum) / n);
}

/** Angle of the envelope's largest value along the arc (0.2° steps, parabolic refinement), and the envelope. */
function wedgeAngle(
  sources: WakeSource[],
  params: WakeParams,
  radius: number,
  wavelength: number,
  side: 1 | -1 = 1,
): { angle: number; env: number[] } {
  const step = 0.2;
  const env: number[] = [];
  for (let d = 0; d <= 40 + 1e-9; d += step) env.push(envelope(sources, params, radius, wavelength, side * d));
  let best = 1;
  for (let i = 1; i < env.length - 1; i++) if (env[i] > env[best]) best = i;
  const [y0, y1, y2] = [env[best - 1], env[best], env[best + 1]];
  return { angle: (best + (y0 - y2) / (2 * (y0 - 2 * y1 + y2))) * step, env };
}

/** Mean distance between successive upward zero crossings of η along the track, from 3 to 8 wavelengths behind. */
function axisWavelength(sources: WakeSource[], params: WakeParams, expected: number): number {
  const crossings: number[] = [];
  const dx = expected / 64;
  let prev = wakeHeightAndGradient(-3 * expected, 0, sources, params)[0];
  for (let x = 3 * expected + dx; x <= 8 * expected; x += dx) {
    const h = wakeHeightAndGradient(-x, 0, sources, params)[0];
    if (prev < 0 && h >= 0) crossings.push(x - dx + (dx * -prev) / (h - prev));
    prev = h;
  }
  return (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
}

// The three speeds of the wedge and wavelength tests, Fr = 0.40, 0.45, 0.51 for the 8 m hull.
const SPEEDS = [3.5, 4, 4.5];

describe('Kelvin wake of a boat sailing straight on a flat sea (CPU twin)', () => {
  // Measured (0.2° steps, parabolic peak, R = 14 λ): 18.28°, 18.31°, 18.26° at 3.5, 4, 4.5 m/s,
  // the same on both sides; envelope beyond 25° at most 2.1 % of the peak. The peak is the
  // first maximum of the Airy function that smooths the cusp, which lies inside the caustic
  // by an angle ∝ (k₀R)^(−2/3): 17.95–17.99° at R = 10 λ, 1.2° short at 14 λ, which is about
  // as far as the 78 s of recorded track reach at these speeds. The tolerance is the issue's.
  it.each(SPEEDS)(
    'puts the largest amplitude within 1.5° of 19.47° on both sides, at U = %s m/s',
    (speed) => {
      const sources = straightSources(speed);
      const wavelength = (2 * Math.PI * speed * speed) / GRAVITY;
      for (const side of [1, -1] as const) {
        const { angle, env } = wedgeAngle(sources, PARAMS, 14 * wavelength, wavelength, side);
        if (process.env.WAKE_REPORT)
          console.log(
            `U=${speed} side=${side} angle=${angle.toFixed(2)} beyond25=${(Math.max(...env.slice(125)) / Math.max(...env)).toFixed(3)} at10λ=${wedgeAngle(sources, PARAMS, 10 * wavelength, wavelength, side).angle.toFixed(2)}`,
          );
        expect(Math.abs(angle - KELVIN_DEG)).toBeLessThan(1.5);
        // The wedge is closed: beyond 25° the envelope is under 10 % of its peak (measured ≤ 3 %).
        const peak = Math.max(...env);
        expect(Math.max(...env.slice(Math.round(25 / 0.2)))).toBeLessThan(0.1 * peak);
      }
    },
    HEAVY_TIMEOUT,
  );

  // Measured (upward zero crossings 3–8 λ behind): 7.798 m for 7.846 (−0.61 %), 10.257 m
  // for 10.248 (+0.09 %), 12.945 m for 12.970 (−0.19 %). The tolerance, 5 %.
  it.each(SPEEDS)('has a transverse wavelength within five percent of 2πU²/g along the track, at U = %s m/s', (speed) => {
    const expected = (2 * Math.PI * speed * speed) / GRAVITY;
    const measured = axisWavelength(straightSources(speed), PARAMS, expected);
    if (process.env.WAKE_REPORT)
      console.log(
        `U=${speed} wavelength=${measured.toFixed(3)} expected=${expected.toFixed(3)} err=${((measured / expected - 1) * 100).toFixed(2)}%`,
      );
    expect(Math.abs(measured / expected - 1)).toBeLessThan(0.05);
  });

  // Measured: +12.3 % with ω ∝ k^0.6, −9.3 % with g 10 % high; the angle control reads 24.0°.
  it('fails the wavelength test with a wrong dispersion relation (negative control: ω ∝ k^0.6)', () => {
    const speed = 4;
    const expected = (2 * Math.PI * speed * speed) / GRAVITY;
    const measured = axisWavelength(straightSources(speed), { ...PARAMS, dispersionPower: 0.6 }, expected);
    if (process.env.WAKE_REPORT) console.log(`control n=0.6 err=${((measured / expected - 1) * 100).toFixed(2)}%`);
    expect(Math.abs(measured / expected - 1)).toBeGreaterThan(0.05);
  });

  it('fails the wavelength test with gravity 10 % off in the model (negative control)', () => {
    const speed = 4;
    const expected = (2 * Math.PI * speed * speed) / GRAVITY;
    const measured = axisWavelength(straightSources(speed), { ...PARAMS, gravity: GRAVITY * 1.1 }, expected);
    if (process.env.WAKE_REPORT) console.log(`control g×1.1 err=${((measured / expected - 1) * 100).toFixed(2)}%`);
    expect(Math.abs(measured / expected - 1)).toBeGreaterThan(0.05);
  });

  it(
    'fails the angle test with a wrong dispersion relation (negative control: ω ∝ k^0.6)',
    () => {
      const speed = 4;
      const wavelength = (2 * Math.PI * speed * speed) / GRAVITY;
      const { angle } = wedgeAngle(straightSources(speed), { ...PARAMS, dispersionPower: 0.6 }, 14 * wavelength, wavelength);
      if (process.env.WAKE_REPORT) console.log(`control n=0.6 angle=${angle.toFixed(2)}`);
      expect(Math.abs(angle - KELVIN_DEG)).toBeGreaterThan(1.5);
    },
    HEAVY_TIMEOUT,
  );

  // Hull 8 m at 4 m/s and hull 18 m at 6 m/s: Fr = 0.4515 both. Lengths scale by 2.25,
  // times by √2.25 = 1.5. Only the history taper, fixed in seconds, breaks the similarity,
  // so the points are ones whose waves are younger than the taper. Measured 0.27 % of the
  // largest |η| apart (62 % with the hull left at 8 m), so 1 %.
  function similarityGap(hullB: number): number {
    const a = straightSources(4);
    const scaled: WakeSource[] = a.map((s) => ({ x: s.x * 2.25, z: s.z * 2.25, age: s.age * 1.5, speed: s.speed * 1.5 }));
    let gap = 0;
    let size = 0;
    for (const [x, z] of [
      [-30, 5],
      [-50, -12],
      [-45, 0],
      [-20, 6],
      [-12, 3],
    ] as const) {
      const hA = wakeHeightAndGradient(x, z, a, PARAMS)[0];
      const hB = wakeHeightAndGradient(x * 2.25, z * 2.25, scaled, { ...PARAMS, hullLength: hullB })[0] / 2.25;
      gap = Math.max(gap, Math.abs(hB - hA));
      size = Math.max(size, Math.abs(hA));
    }
    return gap / size;
  }

  it('scales with the Froude number: the same Fr and the same x/L give the same η/L', () => {
    expect(froudeNumber(4, 8)).toBeCloseTo(froudeNumber(6, 18), 12);
    expect(similarityGap(18)).toBeLessThan(0.01);
  });

  it('breaks the similarity when the hull length is not scaled with the speed (negative control)', () => {
    expect(similarityGap(8)).toBeGreaterThan(0.01);
  });

  it('the gradient it returns for normals matches finite differences within 15 % of the slope scale', () => {
    const sources = straightSources(4);
    let worst = 0;
    let scale = 0;
    for (const [x, z] of [
      [-40, 3],
      [-60, 15],
      [-25, -6],
      [-90, 20],
    ] as const) {
      const [, gx, gz] = wakeHeightAndGradient(x, z, sources, PARAMS);
      const e = 1e-3;
      const fx = (wakeHeightAndGradient(x + e, z, sources, PARAMS)[0] - wakeHeightAndGradient(x - e, z, sources, PARAMS)[0]) / (2 * e);
      const fz = (wakeHeightAndGradient(x, z + e, sources, PARAMS)[0] - wakeHeightAndGradient(x, z - e, sources, PARAMS)[0]) / (2 * e);
      worst = Math.max(worst, Math.hypot(gx - fx, gz - fz));
      scale = Math.max(scale, Math.hypot(fx, fz));
    }
    expect(worst).toBeLessThan(0.15 * scale);
  });
});

describe('Kelvin wake of a turning boat', () => {
  /**
   * Where the wake is centred across the recorded path, at path points `ages` seconds
   * behind the boat: the η²-weighted mean of the offset along the path's normal, inside
   * ±12° (the transverse waves, inside the cusps), pooled over nine path points spread over
   * one wavelength along the path so the crests' phase averages out.
   */
  function centrelineOffsets(sources: WakeSource[], path: [number, number][], originX: number, originZ: number, speed: number): number[] {
    const offsets: number[] = [];
    const crestAge = (2 * Math.PI * speed) / GRAVITY; // one wavelength's sailing time
    for (let age = 4; age <= 20; age += 2) {
      let w = 0;
      let m = 0;
      for (let j = -4; j <= 4; j++) {
        const i = Math.round((age + (j * crestAge) / 8) / FRAME);
        const [px, pz] = path[i];
        const [qx, qz] = path[i + 3];
        const len = Math.hypot(px - qx, pz - qz);
        const nx = -(pz - qz) / len;
        const nz = (px - qx) / len;
        const half = Math.tan((12 * Math.PI) / 180) * speed * age;
        for (let k = -40; k <= 40; k++) {
          const s = (k / 40) * half;
          const h = wakeHeightAndGradient(px + nx * s - originX, pz + nz * s - originZ, sources, PARAMS)[0];
          w += h * h;
          m += h * h * s;
        }
      }
      offsets.push(m / w);
    }
    return offsets;
  }

  // A 4 m/s boat turning at 0.05 rad/s: a circle of 80 m radius. Measured offsets 4–20 s
  // behind: 0.1, −0.1, 0.5, 0.7, 0.1, 0.8, 1.4, 1.3, 1.6 m (drifting outwards with age: the
  // transverse waves run on along the heading they were made with).
  it(
    'keeps the wake centred on the recorded path within 3 m',
    () => {
      const { track, path, time } = sail(4, 60, 0.05);
      const head = track.points()[0];
      const sources = wakeSources(track.points(), time, head.x, head.z);
      const offsets = centrelineOffsets(sources, path, head.x, head.z, 4);
      expect(Math.max(...offsets.map(Math.abs))).toBeLessThan(3);
    },
    HEAVY_TIMEOUT,
  );

  // Measured: up to 14.1 m off by 20 s behind.
  it(
    'misses the path by far more when the sources are laid on a straight line (negative control)',
    () => {
      const { track, path, time } = sail(4, 60, 0.05);
      const head = track.points()[0];
      const real = wakeSources(track.points(), time, head.x, head.z);
      // Same ages, but every source behind the boat along its current heading.
      const [hx, hz] = [path[0][0] - path[3][0], path[0][1] - path[3][1]];
      const l = Math.hypot(hx, hz);
      const straight = real.map((s) => ({ ...s, x: (-hx / l) * 4 * s.age, z: (-hz / l) * 4 * s.age }));
      const offsets = centrelineOffsets(straight, path, head.x, head.z, 4);
      expect(Math.max(...offsets.map(Math.abs))).toBeGreaterThan(3);
    },
    HEAVY_TIMEOUT,
  );
});

describe('wakeHeight', () => {
  it('is zero with the strength at zero and on a track of one point', () => {
    const { track, time } = sail(4, 20);
    const head = track.points()[0];
    const [x, z] = [head.x - 20, head.z + 3];
    expect(wakeHeight(x, z, time, track.points(), { ...PARAMS, strength: 0 })).toBe(0);
    expect(wakeHeight(x, z, time, track.points().slice(0, 1), PARAMS)).toBe(0);
    expect(Math.abs(wakeHeight(x, z, time, track.points(), PARAMS))).toBeGreaterThan(0.01);
  });

  it('uses at most TRACK_POINTS sources, and the same wake whatever origin the positions are taken from', () => {
    const { track, time } = sail(4, 200);
    const points = track.points();
    expect(points.length).toBe(TRACK_POINTS);
    const head = points[0];
    const far = wakeSources(points, time, head.x, head.z);
    const near = wakeSources(points, time);
    const a = wakeHeightAndGradient(head.x - 40 - head.x, head.z + 5 - head.z, far, PARAMS)[0];
    const b = wakeHeightAndGradient(head.x - 40, head.z + 5, near, PARAMS)[0];
    expect(a).toBeCloseTo(b, 9);
  });
});
