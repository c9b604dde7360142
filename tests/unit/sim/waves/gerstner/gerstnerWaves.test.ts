import { describe, expect, it } from 'vitest';
import {
  GerstnerWaveModel,
  gerstnerDerivativesAt,
  gerstnerDisplacementAt,
  gerstnerNormalAt,
  gerstnerTimePhases,
  invertGerstner,
  steepnessSum,
  type GerstnerWave,
} from '../../../../../src/sim/waves/gerstner/gerstnerWaves';
import {
  drawGerstnerWaves,
  gerstnerSea,
  limitSteepness,
  linearDispersion,
  wavenumberFor,
} from '../../../../../src/sim/waves/gerstner/gerstnerSpectrum';
import { undoHorizontalDisplacement } from '../../../../../src/sim/waves/waveModel';
import { GERSTNER_MAX_WAVES } from '../../../../../src/render/waves/gerstner/gerstnerWaveUniforms';
import gerstnerGlsl from '../../../../../shaders/waves/gerstner.glsl?raw';
import { G, cosineSquared, jonswap, piersonMoskowitz } from '../../../../support/testSeas';

const TWO_PI = 2 * Math.PI;
/** The inversion sweeps take 1–3 s alone; the shared 2-core machine can triple that. */
const SLOW = 30_000;

/** A sea from the test's PM spectrum (the app's PM, see testSeas.ts). */
function pmSea(u10: number, count: number, seed: number, steepness = 1): GerstnerWave[] {
  return gerstnerSea({ count, seed, spectrum: piersonMoskowitz(u10).spectrum, spreading: cosineSquared, windDirection: 0.3, steepness });
}

/** The same sea with every horizontal amplitude scaled so Σ Qᵢ kᵢ Aᵢ equals `sum` exactly. */
function atSteepness(waves: GerstnerWave[], sum: number): GerstnerWave[] {
  const s = steepnessSum(waves);
  return waves.map((w) => ({ ...w, horizontal: (w.horizontal * sum) / s }));
}

function grid(count: number, spacing: number): [number, number][] {
  const side = Math.round(Math.sqrt(count));
  return Array.from({ length: side * side }, (_, i) => [(i % side) * spacing * 1.13, Math.floor(i / side) * spacing * 0.87]);
}

describe('Gerstner twin against hand-derived values', () => {
  // One wave heading along (3, 4)/5 with λ = 20 m: c = (0.03, 0.04) cycles/m, A = 0.5 m, QA = 0.3 m.
  const wave: GerstnerWave = { cx: 0.03, cz: 0.04, omega: Math.sqrt(G * (TWO_PI / 20)), amplitude: 0.5, horizontal: 0.3, phase: 0 };

  it(
    'at t = 0 and (5, 0): θ = 2π · 0.15 = 54°, so dy = A cos 54°, (dx, dz) = −QA (0.6, 0.8) sin 54°',
    () => {
      // sin 54° = (1 + √5)/4 = 0.80901699, cos 54° = 0.58778525.
      const d = gerstnerDisplacementAt([wave], gerstnerTimePhases([wave], 0), 5, 0);
      expect(d[0]).toBeCloseTo(-0.3 * 0.6 * 0.80901699, 7);
      expect(d[1]).toBeCloseTo(0.5 * 0.58778525, 7);
      expect(d[2]).toBeCloseTo(-0.3 * 0.8 * 0.80901699, 7);
    },
    SLOW,
  );

  it(
    'a quarter period later the angle has fallen by 90°: θ = −36°',
    () => {
      const quarter = TWO_PI / wave.omega / 4;
      const d = gerstnerDisplacementAt([wave], gerstnerTimePhases([wave], quarter), 5, 0);
      // sin(−36°) = −0.58778525, cos(−36°) = 0.80901699.
      expect(d[0]).toBeCloseTo(0.3 * 0.6 * 0.58778525, 7);
      expect(d[1]).toBeCloseTo(0.5 * 0.80901699, 7);
    },
    SLOW,
  );

  it(
    'the normal at the crest of a lone trochoid is straight up, and at θ = 90° tilts by atan(kA / (1 − 0))',
    () => {
      const crest = gerstnerNormalAt([wave], gerstnerTimePhases([wave], 0), 0, 0);
      expect(crest[1]).toBeCloseTo(1, 12);
      // θ = 90° where c·p = 0.25: p = 5 (0.6, 0.8). There cos θ = 0 (no compression) and the
      // slope of the surface along k is ∂dy/∂s = −A |k| sin θ = −A k.
      const n = gerstnerNormalAt([wave], gerstnerTimePhases([wave], 0), 3, 4);
      const kA = (TWO_PI / 20) * 0.5;
      const expected = [0.6 * kA, 1, 0.8 * kA].map((v) => v / Math.hypot(kA, 1));
      for (let i = 0; i < 3; i++) expect(n[i]).toBeCloseTo(expected[i], 10);
    },
    SLOW,
  );

  it(
    'two waves add (superposition of displacement)',
    () => {
      const other: GerstnerWave = { cx: -0.05, cz: 0, omega: Math.sqrt(G * TWO_PI * 0.05), amplitude: 0.2, horizontal: 0.2, phase: 0.25 };
      const p = gerstnerTimePhases([wave, other], 2.5);
      const sum = gerstnerDisplacementAt([wave, other], p, 7, -3);
      const a = gerstnerDisplacementAt([wave], p.subarray(0, 1), 7, -3);
      const b = gerstnerDisplacementAt([other], p.subarray(1, 2), 7, -3);
      for (let i = 0; i < 3; i++) expect(sum[i]).toBeCloseTo(a[i] + b[i], 12);
    },
    SLOW,
  );
});

/** The shader's arithmetic in float32 (Math.fround at every step), sine exact: what a GPU computes. */
function float32Displacement(waves: GerstnerWave[], tau: ArrayLike<number>, x: number, z: number): [number, number, number] {
  const f = Math.fround;
  const fract = (v: number) => f(v - Math.floor(v));
  let dx = 0;
  let dy = 0;
  let dz = 0;
  for (let i = 0; i < waves.length; i++) {
    const w = waves[i];
    const turns = f(f(fract(f(f(w.cx) * f(x))) + fract(f(f(w.cz) * f(z)))) + f(tau[i]));
    const s = f(Math.sin(f(TWO_PI * fract(turns))));
    const c = f(Math.cos(f(TWO_PI * fract(turns))));
    const len = f(Math.hypot(f(w.cx), f(w.cz)));
    dx = f(dx - f(f(f(w.horizontal) * f(f(w.cx) / len)) * s));
    dz = f(dz - f(f(f(w.horizontal) * f(f(w.cz) / len)) * s));
    dy = f(dy + f(f(w.amplitude) * c));
  }
  return [dx, dy, dz];
}

describe('Time phases reduced in double precision keep a float32 shader exact late and far out', () => {
  const sea = pmSea(15, 64, 3);
  const model = new GerstnerWaveModel(sea);
  const points: [number, number][] = [
    [0, 0],
    [1500.37, -1200.5],
    [-2000.25, 1999.75],
  ];

  it(
    'float32 emulation of the shader stays within 1e-4 m of the double twin at t = 10⁶ s, 2 km out',
    () => {
      const t = 1e6;
      const tau = gerstnerTimePhases(sea, t);
      let worst = 0;
      for (const [x, z] of points) {
        const gpu = float32Displacement(sea, tau, x, z);
        const cpu = model.displacement(x, z, t);
        for (let i = 0; i < 3; i++) worst = Math.max(worst, Math.abs(gpu[i] - cpu[i]));
      }
      // Measured 1.1e-5 m (64 waves, Hs 5.0 m); unreduced, 4.4e-2 m (next test).
      expect(worst).toBeLessThan(1e-4);
    },
    SLOW,
  );

  it(
    'negative control: handing the shader the unreduced phase φ − ωt/2π in float32 misses by centimetres',
    () => {
      const t = 1e6;
      const unreduced = sea.map((w) => w.phase - (w.omega / TWO_PI) * t);
      let worst = 0;
      for (const [x, z] of points) {
        const gpu = float32Displacement(sea, unreduced, x, z);
        const cpu = model.displacement(x, z, t);
        for (let i = 0; i < 3; i++) worst = Math.max(worst, Math.abs(gpu[i] - cpu[i]));
      }
      expect(worst).toBeGreaterThan(1e-2);
    },
    SLOW,
  );
});

describe('Analytic normals against finite differences of the twin', () => {
  const sea = pmSea(12, 32, 5);
  const tau = gerstnerTimePhases(sea, 17.25);

  function finiteDifferenceNormal(x: number, z: number, h: number): [number, number, number] {
    const P = (px: number, pz: number) => {
      const d = gerstnerDisplacementAt(sea, tau, px, pz);
      return [px + d[0], d[1], pz + d[2]];
    };
    const a = P(x + h, z);
    const b = P(x - h, z);
    const c = P(x, z + h);
    const e = P(x, z - h);
    const tx = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    const tz = [c[0] - e[0], c[1] - e[1], c[2] - e[2]];
    const n = [tz[1] * tx[2] - tz[2] * tx[1], tz[2] * tx[0] - tz[0] * tx[2], tz[0] * tx[1] - tz[1] * tx[0]];
    const len = Math.hypot(n[0], n[1], n[2]);
    return [n[0] / len, n[1] / len, n[2] / len];
  }

  function worstAngle(normal: (x: number, z: number) => [number, number, number]): number {
    let worst = 0;
    for (const [x, z] of grid(400, 1.7)) {
      const a = normal(x, z);
      const b = finiteDifferenceNormal(x, z, 1e-3);
      worst = Math.max(worst, Math.acos(Math.min(1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));
    }
    return worst;
  }

  it(
    'agree within 1e-6 rad over 400 points (central differences, h = 1 mm)',
    () => {
      // Measured 3e-8 rad, the floor of acos near 1; the height-field control below is 3.1e-2 rad.
      expect(worstAngle((x, z) => gerstnerNormalAt(sea, tau, x, z))).toBeLessThan(1e-6);
    },
    SLOW,
  );

  it(
    'negative control: the height-field normal that ignores the horizontal motion is off by far more',
    () => {
      const heightFieldNormal = (x: number, z: number): [number, number, number] => {
        const d = gerstnerDerivativesAt(sea, tau, x, z);
        const len = Math.hypot(d.dydx, 1, d.dydz);
        return [-d.dydx / len, 1 / len, -d.dydz / len];
      };
      expect(worstAngle(heightFieldNormal)).toBeGreaterThan(1e-2);
    },
    SLOW,
  );
});

describe('Steepness limit: Σ Qᵢ kᵢ Aᵢ ≤ Q ≤ 1, so crests never loop', () => {
  it.each([4, 16, 64])(
    'holds for PM and short-fetch JONSWAP seas, %i waves, seeds 1–5, Q = 1',
    (count) => {
      for (let seed = 1; seed <= 5; seed++) {
        for (const spectrum of [piersonMoskowitz(10).spectrum, jonswap(15, 20e3).spectrum]) {
          const waves = gerstnerSea({ count, seed, spectrum, spreading: cosineSquared, windDirection: 0, steepness: 1 });
          expect(steepnessSum(waves)).toBeLessThanOrEqual(1 + 1e-12);
          // Each wave is at most Gerstner's own trochoid (Q = 1: circular orbits).
          for (const w of waves) expect(w.horizontal).toBeLessThanOrEqual(w.amplitude * (1 + 1e-12));
        }
      }
    },
    SLOW,
  );

  it(
    "a sea steeper than the limit (Σ kA > 1: PM's waves at twice their height) is scaled to exactly Q",
    () => {
      const drawn = drawGerstnerWaves({
        count: 64,
        seed: 2,
        spectrum: piersonMoskowitz(10).spectrum,
        spreading: cosineSquared,
        windDirection: 0,
        steepness: 1,
      });
      const waves = drawn.map((w) => ({ ...w, amplitude: 2 * w.amplitude }));
      const slope = steepnessSum(waves.map((w) => ({ ...w, horizontal: w.amplitude })));
      expect(slope).toBeGreaterThan(1);
      for (const q of [0.2, 0.6, 1]) expect(steepnessSum(limitSteepness(waves, q))).toBeCloseTo(q, 12);
    },
    SLOW,
  );

  it(
    'rejects Q outside [0, 1]',
    () => {
      expect(() => limitSteepness(pmSea(10, 4, 1), 1.2)).toThrow(/Steepness/);
    },
    SLOW,
  );

  function smallestJacobian(waves: GerstnerWave[]): number {
    const tau = gerstnerTimePhases(waves, 0);
    let smallest = Infinity;
    for (const [x, z] of grid(40000, 0.5)) {
      const d = gerstnerDerivativesAt(waves, tau, x, z);
      smallest = Math.min(smallest, (1 + d.dxdx) * (1 + d.dzdz) - d.dxdz * d.dxdz);
    }
    return smallest;
  }

  it(
    'at the limit the horizontal map never folds: det J ≥ 0 on 40 000 points (4 waves, Σ QkA = 1)',
    () => {
      // Measured minimum 0.126: the four crests never all meet on this patch; at Σ QkA = 2, −0.73.
      expect(smallestJacobian(atSteepness(pmSea(10, 4, 1), 1))).toBeGreaterThanOrEqual(0);
    },
    SLOW,
  );

  it(
    'negative control: past the limit (Σ QkA = 2) the same sea folds over (det J < 0: a looped crest)',
    () => {
      expect(smallestJacobian(atSteepness(pmSea(10, 4, 1), 2))).toBeLessThan(0);
    },
    SLOW,
  );
});

describe('Inverting the horizontal motion (sample at a world point)', () => {
  function worstResidual(waves: GerstnerWave[], invert: (tau: Float64Array, x: number, z: number) => number): number {
    const tau = gerstnerTimePhases(waves, 0);
    let worst = 0;
    for (const [x, z] of grid(1600, 2.5)) worst = Math.max(worst, invert(tau, x, z));
    return worst;
  }

  it.each([4, 16, 64])(
    'Newton, 3 evaluations: residual < 1 mm on PM seas (U = 20 m/s, Q = 1, %i waves, seeds 1–3)',
    (count) => {
      for (let seed = 1; seed <= 3; seed++) {
        const sea = pmSea(20, count, seed);
        // Measured worst 3.1e-6 m over seeds 1–5.
        expect(worstResidual(sea, (tau, x, z) => invertGerstner(sea, tau, x, z, 3).residual)).toBeLessThan(1e-3);
      }
    },
    SLOW,
  );

  it.each([
    [4, 5],
    [8, 4],
    [16, 4],
    [64, 4],
  ])(
    'at the hard limit Σ QkA = 1, %i waves: residual < 1 mm in %i evaluations (seeds 1–3)',
    (count, steps) => {
      for (let seed = 1; seed <= 3; seed++) {
        const sea = atSteepness(pmSea(20, count, seed), 1);
        // Measured worst over seeds 1–5: 1.0e-4 m (4 waves, 5 steps), 1.8e-5 m (16 waves, 4 steps).
        expect(worstResidual(sea, (tau, x, z) => invertGerstner(sea, tau, x, z, steps).residual)).toBeLessThan(1e-3);
      }
    },
    SLOW,
  );

  it(
    'negative control: plain fixed-point (the seam default, 4 steps) does not reach 1 mm at the limit',
    () => {
      const sea = atSteepness(pmSea(20, 16, 1), 1);
      const worst = worstResidual(
        sea,
        (tau, x, z) => undoHorizontalDisplacement((px, pz) => gerstnerDisplacementAt(sea, tau, px, pz), x, z, 4).residual,
      );
      // Measured 0.20 m: its error shrinks by only |∂Dₕ/∂p| → 1 per step near an aligned crest.
      expect(worst).toBeGreaterThan(1e-2);
    },
    SLOW,
  );

  it(
    'negative control: Newton with a planted sign error in the Jacobian fails',
    () => {
      const sea = pmSea(20, 16, 1);
      const flipped = sea.map((w) => ({ ...w, horizontal: -w.horizontal }));
      // Invert sea A using derivatives of sea B: the step direction is wrong where the chop matters.
      const worst = worstResidual(sea, (tau, x, z) => {
        let px = x;
        let pz = z;
        for (let i = 0; i < 4; i++) {
          const d = gerstnerDisplacementAt(sea, tau, px, pz);
          const j = gerstnerDerivativesAt(flipped, tau, px, pz);
          const a = 1 + j.dxdx;
          const b = j.dxdz;
          const c = 1 + j.dzdz;
          const det = a * c - b * b;
          const rx = px + d[0] - x;
          const rz = pz + d[2] - z;
          px -= (c * rx - b * rz) / det;
          pz -= (a * rz - b * rx) / det;
        }
        const d = gerstnerDisplacementAt(sea, tau, px, pz);
        return Math.hypot(px + d[0] - x, pz + d[2] - z);
      });
      expect(worst).toBeGreaterThan(1e-3);
    },
    SLOW,
  );

  it(
    'sample() returns the height and normal of the grid point that lands on the query point',
    () => {
      const sea = pmSea(14, 32, 9);
      const model = new GerstnerWaveModel(sea);
      const t = 123.4;
      for (const [x, z] of grid(100, 3.1)) {
        const s = model.sample(x, z, t);
        const p = invertGerstner(sea, gerstnerTimePhases(sea, t), x, z);
        const d = model.displacement(p.x, p.z, t);
        expect(Math.hypot(p.x + d[0] - x, p.z + d[2] - z)).toBeLessThan(1e-6);
        expect(s.height).toBeCloseTo(d[1], 12);
        expect(s.normal).toEqual(model.normal(p.x, p.z, t));
      }
    },
    SLOW,
  );
});

describe('Waves drawn from a spectrum', () => {
  const pm = piersonMoskowitz(10);
  const options = { count: 32, seed: 11, spectrum: pm.spectrum, spreading: cosineSquared, windDirection: 1.0, steepness: 0.8 };

  it(
    'is deterministic in the seed, and another seed gives another sea',
    () => {
      expect(gerstnerSea(options)).toEqual(gerstnerSea(options));
      expect(gerstnerSea({ ...options, seed: 12 })).not.toEqual(gerstnerSea(options));
    },
    SLOW,
  );

  it(
    "keeps the band's variance: Σ Aᵢ²/2 = 0.989 m₀, so 4√(Σ Aᵢ²/2) is within 1 % of PM's Hs",
    () => {
      const waves = gerstnerSea(options);
      const m0 = waves.reduce((s, w) => s + (w.amplitude * w.amplitude) / 2, 0);
      // PM's Hs = 0.21 U₁₉.₅²/g is the rounded form of 4√(α / 4β) U²/g = 0.2092: 0.4 % apart.
      expect(4 * Math.sqrt(m0)).toBeCloseTo(Math.sqrt(0.989) * pm.hs, 1);
      expect(Math.abs((4 * Math.sqrt(m0)) / pm.hs - 1)).toBeLessThan(0.01);
    },
    SLOW,
  );

  it(
    'heads the waves downwind (cos² spreading: every wave within ±90° of the wind, mean near it)',
    () => {
      const waves = gerstnerSea({ ...options, count: 64 });
      let sx = 0;
      let sz = 0;
      for (const w of waves) {
        const heading = Math.atan2(w.cz, w.cx) - options.windDirection;
        expect(Math.cos(heading)).toBeGreaterThanOrEqual(0);
        sx += Math.cos(heading);
        sz += Math.sin(heading);
      }
      expect(Math.abs(Math.atan2(sz, sx))).toBeLessThan(0.15);
    },
    SLOW,
  );

  it(
    'gives each wave the k of the dispersion relation passed in (finite depth 8 m)',
    () => {
      const dispersion = linearDispersion(8);
      for (const w of gerstnerSea({ ...options, dispersion })) {
        const k = TWO_PI * Math.hypot(w.cx, w.cz);
        expect(Math.sqrt(G * k * Math.tanh(8 * k))).toBeCloseTo(w.omega, 9);
      }
      expect(wavenumberFor(1, linearDispersion())).toBeCloseTo(1 / G, 12);
    },
    SLOW,
  );

  it(
    'bounds() hold every displacement on a patch',
    () => {
      const model = new GerstnerWaveModel(gerstnerSea(options));
      const b = model.bounds();
      for (const [x, z] of grid(900, 1.9)) {
        const d = model.displacement(x, z, 40);
        expect(Math.abs(d[1])).toBeLessThanOrEqual(b.vertical);
        expect(Math.hypot(d[0], d[2])).toBeLessThanOrEqual(b.horizontal);
      }
    },
    SLOW,
  );
});

describe('GLSL chunk and its uniforms helper agree', () => {
  it(
    "declare the same maximum wave count and the seam's two functions",
    () => {
      expect(gerstnerGlsl).toMatch(new RegExp(`#define GERSTNER_MAX_WAVES ${GERSTNER_MAX_WAVES}\\b`));
      expect(gerstnerGlsl).toMatch(/vec3 waveDisplacement\(vec2 gridXZ\)/);
      expect(gerstnerGlsl).toMatch(/vec3 waveNormal\(vec2 gridXZ\)/);
      for (const name of ['uGerstnerCount', 'uGerstnerWaves', 'uGerstnerPhases'])
        expect(gerstnerGlsl).toMatch(new RegExp(`uniform \\w+ ${name}\\b`));
    },
    SLOW,
  );
});
