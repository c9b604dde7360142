import { describe, expect, it } from 'vitest';
import {
  fittedVerticalDerivativeKernel,
  kernelOrbitWeights,
  kernelResponse,
  tessendorfKernel,
  waveEquationKernel,
  IWAVE_KERNEL_BAND,
  IWAVE_KERNEL_ORBITS,
  type ConvolutionKernel,
} from '../../../../src/sim/iwave/verticalDerivativeKernel';
import { GRAVITY, IWAVE_SPONGE, IWaveGrid, type SpongeLayer } from '../../../../src/sim/iwave/iwaveGrid';
import { crestRadii, waveFrontRadius } from '../../../../src/sim/iwave/cauchyPoissonRings';
import { equationKernels, WAVE_EQUATION_SPEED } from '../../../../src/sim/iwave/interactiveField';

/**
 * iWave against physics, on the CPU reference solver: the dispersion of the discrete operator
 * (ω² = g k), the Cauchy–Poisson rings of a dropped stone, and determinism. Each check runs a
 * negative control: the plain wave equation, which is not dispersive, fails it.
 */
const g = GRAVITY;
const spacing = 0.5;
const fitted = fittedVerticalDerivativeKernel();

/** ω² / (g k) − 1 for the Fourier mode (m, m·diagonal) of a periodic 64² box, from the period of its evolved amplitude. */
function measuredDispersionError(kernel: ConvolutionKernel, m: number, diagonal: boolean): { k: number; error: number } {
  const n = 64;
  const dt = 1 / 30;
  const grid = new IWaveGrid({ n, spacing, kernel, wrap: 'xz' });
  const kx = (2 * Math.PI * m) / (n * spacing);
  const kz = diagonal ? kx : 0;
  const mode = new Float64Array(n * n);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) mode[j * n + i] = Math.cos(kx * grid.texelX(i) + kz * grid.texelZ(j));
  grid.height.set(mode);
  grid.previous.set(mode);
  const amplitude = () => grid.height.reduce((s, h, c) => s + h * mode[c], 0);
  const k = Math.hypot(kx, kz);
  const steps = Math.ceil((3 * 2 * Math.PI) / Math.sqrt(g * k) / dt) + 30;
  const crossings: number[] = [];
  let before = amplitude();
  for (let s = 1; s <= steps; s++) {
    grid.step(dt);
    const now = amplitude();
    if (before > 0 !== now > 0) crossings.push((s - 1 + before / (before - now)) * dt);
    before = now;
  }
  const period = (2 * (crossings[crossings.length - 1] - crossings[0])) / (crossings.length - 1);
  const omega = (2 * Math.PI) / period;
  return { k, error: (omega * omega) / (g * k) - 1 };
}

describe('the dispersion of the vertical-derivative kernel', () => {
  // Modes of the 64² box (0.5 m texels) inside the band, along an axis and the diagonal.
  const modes: [number, boolean][] = [
    [3, false],
    [2, true],
    [4, false],
    [3, true],
    [6, false],
    [6, true],
    [8, false],
    [10, false],
    [10, true],
    [12, false],
    [15, false],
    [15, true],
  ];

  // Planted fault: the wave equation fails.
  it('evolves single Fourier modes with ω² = g k within 5 % from k = 0.55 to 4.2 rad/m', () => {
    const measured = modes.map(([m, d]) => measuredDispersionError(fitted, m, d));
    console.log(`iWave dispersion, ω²/(gk) − 1: ${measured.map((r) => `k ${r.k.toFixed(2)}: ${(100 * r.error).toFixed(2)} %`).join(', ')}`);
    expect(Math.min(...measured.map((r) => r.k))).toBeLessThan(0.6);
    expect(Math.max(...measured.map((r) => r.k))).toBeGreaterThan(4);
    for (const r of measured) expect(Math.abs(r.error)).toBeLessThan(0.05);
    // Negative control: ∂²h/∂t² = c²∇²h with c the phase speed of a 4 m wave, ω² = c²k².
    const control = modes.map(([m, d]) =>
      measuredDispersionError(waveEquationKernel(Math.sqrt(g / ((2 * Math.PI) / 4)), spacing, g), m, d),
    );
    console.log(`Wave equation, ω²/(gk) − 1: ${control.map((r) => `${(100 * r.error).toFixed(0)} %`).join(', ')}`);
    expect(control.filter((r) => Math.abs(r.error) > 0.05).length).toBeGreaterThan(modes.length / 2);
  }, 120_000);

  // A smaller kernel sits inside with zeros; a lopsided one throws.
  it('packs into 28 orbit weights, one per mirror-image set, that give the kernel back', () => {
    const weights = kernelOrbitWeights(fitted);
    expect(weights.length).toBe(IWAVE_KERNEL_ORBITS);
    expect(IWAVE_KERNEL_ORBITS).toBe(28);
    // Orbit 0 is the centre tap, orbit 1 (1, 0), orbit 2 (1, 1), orbit 27 (6, 6).
    expect(weights[0]).toBe(Math.fround(fitted.weights[6 * 13 + 6]));
    expect(weights[1]).toBe(Math.fround(fitted.weights[6 * 13 + 7]));
    expect(weights[2]).toBe(Math.fround(fitted.weights[7 * 13 + 7]));
    expect(weights[27]).toBe(Math.fround(fitted.weights[12 * 13 + 12]));
    const wave = kernelOrbitWeights(waveEquationKernel(2, spacing, g));
    expect(Array.from(wave.slice(3))).toEqual(new Array(25).fill(0));
    const lopsided = fittedVerticalDerivativeKernel();
    lopsided.weights[6 * 13 + 7] += 1e-3;
    expect(() => kernelOrbitWeights(lopsided)).toThrow(/not symmetric/);
  });

  // The response stays positive over the whole Brillouin zone; Tessendorf's truncated Bessel kernel does not.
  it('keeps every mode stable and within 5 % of |k| across the band', () => {
    const worstInBand = (kernel: ConvolutionKernel) => {
      let worst = 0;
      for (let s = 0; s <= 40; s++) {
        const k = IWAVE_KERNEL_BAND[0] * (IWAVE_KERNEL_BAND[1] / IWAVE_KERNEL_BAND[0]) ** (s / 40);
        for (let a = 0; a <= 6; a++) {
          const angle = (a / 6) * (Math.PI / 4);
          worst = Math.max(worst, Math.abs(kernelResponse(kernel, k * Math.cos(angle), k * Math.sin(angle)) / k - 1));
        }
      }
      return worst;
    };
    let lowest = Infinity;
    for (let q = 0; q <= 60; q++)
      for (let p = 0; p <= 60; p++)
        lowest = Math.min(lowest, kernelResponse(fitted, -Math.PI + (2 * Math.PI * p) / 60, -Math.PI + (2 * Math.PI * q) / 60));
    expect(lowest).toBeGreaterThan(0.1);
    const fittedWorst = worstInBand(fitted);
    const tessendorfWorst = worstInBand(tessendorfKernel());
    console.log(
      `Kernel response vs |k| over ${IWAVE_KERNEL_BAND.join('–')} rad/texel: fitted ${(100 * fittedWorst).toFixed(1)} %, Tessendorf σ = 1 ${(100 * tessendorfWorst).toFixed(0)} %; R(0) = ${kernelResponse(fitted, 0, 0).toFixed(3)}`,
    );
    expect(fittedWorst).toBeLessThan(0.05);
    expect(tessendorfWorst).toBeGreaterThan(0.05);
  }, 60_000);
});

/** Crests (local maxima above zero, highest within ±0.6 m) along a ray from the origin, between rMin and rMax metres. */
function crestsAlong(grid: IWaveGrid, angle: number, rMin: number, rMax: number): number[] {
  const step = 0.05;
  const at = (r: number) => grid.sample(r * Math.cos(angle), r * Math.sin(angle));
  const crests: number[] = [];
  for (let r = rMin; r < rMax; r += step) {
    const b = at(r);
    let top = b > 0;
    for (let q = -12; q <= 12 && top; q++) if (at(r + q * step) > b) top = false;
    if (!top) continue;
    const a = at(r - step);
    const c = at(r + step);
    const curvature = a - 2 * b + c;
    crests.push(r + (curvature !== 0 ? (0.5 * step * (a - c)) / curvature : 0));
  }
  return crests;
}

interface RingCheck {
  t: number;
  radius: number;
  measured: number;
  theory: number;
}

/**
 * A stone (a 0.2 m Gaussian bump of radius 1.5 m) dropped at the origin of a calm 96 m square,
 * then at t = 8, 10 and 12 s, along two rays: each pair of neighbouring crests r₁ < r₂ in the
 * stationary-phase region (phase g t²/(4 r₂) ≥ 12 rad) whose wavenumber lies where the stone
 * and the grid carry waves (0.8 – 2.5 rad/m). Crests stand where g t²/(4 r) steps by 2π, so
 * their spacing gives k = 2π/(r₂ − r₁), against Cauchy–Poisson's g t²/(4 r₁ r₂) (k = g t²/(4r²)
 * at r = √(r₁ r₂)).
 */
function ringChecks(kernel: ConvolutionKernel): RingCheck[] {
  const grid = new IWaveGrid({ n: 192, spacing, kernel, sponge: { width: 24, strength: 4 } });
  grid.disturb({ x: 0, z: 0, radius: 1.5, height: 0.2 });
  const dt = 1 / 30;
  const checks: RingCheck[] = [];
  let steps = 0;
  for (const t of [8, 10, 12]) {
    while (steps < Math.round(t / dt)) {
      grid.step(dt);
      steps++;
    }
    for (const angle of [0, Math.PI / 6]) {
      const crests = crestsAlong(grid, angle, 4, (g * t * t) / (4 * 12));
      for (let q = 1; q < crests.length; q++) {
        const [r1, r2] = [crests[q - 1], crests[q]];
        const theory = (g * t * t) / (4 * r1 * r2);
        if (theory < 0.8 || theory > 2.5) continue;
        checks.push({ t, radius: Math.sqrt(r1 * r2), measured: (2 * Math.PI) / (r2 - r1), theory });
      }
    }
  }
  return checks;
}

describe('a dropped stone (Cauchy–Poisson)', () => {
  // Long waves lead (planted fault: the wave equation fails).
  it('spaces its crests as k = g t²/(4 r²) within 15 %, at several radii and three times', () => {
    const checks = ringChecks(fitted);
    console.log(
      `Cauchy–Poisson: ${checks.map((c) => `t ${c.t} s, r ${c.radius.toFixed(1)} m: k ${c.measured.toFixed(2)} vs ${c.theory.toFixed(2)} (${(100 * (c.measured / c.theory - 1)).toFixed(1)} %)`).join('; ')}`,
    );
    for (const t of [8, 10, 12]) expect(checks.filter((c) => c.t === t).length).toBeGreaterThanOrEqual(2);
    for (const c of checks) expect(Math.abs(c.measured / c.theory - 1)).toBeLessThan(0.15);
    // Long waves ahead, short behind: along each time's checks the wavenumber falls outwards.
    for (const t of [10, 12]) {
      const ray = checks.filter((c) => c.t === t).sort((a, b) => a.radius - b.radius);
      expect(ray[0].measured).toBeGreaterThan(ray[ray.length - 1].measured);
    }
    // Negative control: a non-dispersive sea (c of a 1.5 rad/m wave) makes a ring of one speed.
    const control = ringChecks(waveEquationKernel(Math.sqrt(g / 1.5), spacing, g));
    const passing = control.filter((c) => Math.abs(c.measured / c.theory - 1) < 0.15);
    console.log(`Wave equation: ${passing.length} of ${control.length} crest pairs within 15 %`);
    expect(passing.length).toBeLessThan(checks.length / 2);
  }, 180_000);
});

/** Crests (local maxima above zero) along +x from a stone at the origin, between rMin and rMax metres, sampled every 5 cm. */
function crestsOnAxis(grid: IWaveGrid, rMin: number, rMax: number): number[] {
  const crests: number[] = [];
  for (let r = rMin; r < rMax; r += 0.05) {
    const b = grid.sample(r, 0);
    if (b > 0 && b > grid.sample(r - 0.05, 0) && b >= grid.sample(r + 0.05, 0)) crests.push(r);
  }
  return crests;
}

describe('the guide rings of the stone preset', () => {
  // From the phase g t²/(4r) (Lamb §255) (planted fault: half a turn off, the troughs, miss).
  it("stand where the solver's crests are, r = g t²/(8πn), within one texel at t = 8 and 10 s", () => {
    const grid = new IWaveGrid({ n: 160, spacing, kernel: fitted, sponge: { width: 20, strength: 4 } });
    grid.disturb({ x: 0, z: 0, radius: 1, height: 0.4 });
    const dt = 1 / 30;
    let steps = 0;
    const nearest = (crests: number[], r: number) => Math.min(...crests.map((c) => Math.abs(c - r)));
    for (const t of [8, 10]) {
      while (steps < Math.round(t / dt)) {
        grid.step(dt);
        steps++;
      }
      const crests = crestsOnAxis(grid, 3, 30);
      const rings = crestRadii(t, { kMin: 0.6, kMax: 4.4, maxRadius: 30 });
      console.log(
        `t ${t} s: guide rings ${rings.map((r) => r.toFixed(2)).join(', ')} m; the solver's crests ${crests.map((r) => r.toFixed(2)).join(', ')} m`,
      );
      expect(rings.length).toBeGreaterThanOrEqual(3);
      for (const r of rings) expect(nearest(crests, r)).toBeLessThan(spacing);
      // Planted fault: rings where the phase is π off (troughs): most are more than a texel from a crest.
      const troughs = rings.map((r) => (g * t * t) / (4 * ((g * t * t) / (4 * r) + Math.PI)));
      expect(troughs.filter((r) => nearest(crests, r) < spacing).length).toBeLessThan(troughs.length / 2);
    }
    // k at each ring is g t²/(4r²), the formula of the issue: 16π²n²/(g t²).
    expect(crestRadii(10, { kMin: 0.6, kMax: 4.4, maxRadius: 100 })[0]).toBeCloseTo((g * 100) / (16 * Math.PI), 12);
  }, 120_000);
});

describe('the wave equation beside iWave (stone-compare)', () => {
  it('keeps the halves apart, and runs one ring at c on the right where iWave spreads a train on the left', () => {
    const { kernel, rightKernel } = equationKernels('side-by-side', spacing);
    const grid = new IWaveGrid({ n: 256, spacing, kernel, rightKernel, sponge: IWAVE_SPONGE });
    grid.disturb({ x: -28, z: 0, radius: 1, height: 0.4 });
    grid.disturb({ x: 28, z: 0, radius: 1, height: 0.4 });
    const single = new IWaveGrid({ n: 256, spacing, kernel, rightKernel, sponge: IWAVE_SPONGE });
    single.disturb({ x: -28, z: 0, radius: 1, height: 0.4 });
    const dt = 1 / 30;
    for (let s = 0; s < 180; s++) {
      grid.step(dt);
      single.step(dt);
    }
    let leak = 0;
    let left = 0;
    for (let j = 0; j < 256; j++) {
      for (let i = 0; i < 256; i++) {
        const h = Math.abs(single.height[j * 256 + i]);
        if (i >= 128) leak = Math.max(leak, h);
        else left = Math.max(left, h);
      }
    }
    console.log(`A stone in the left half only, 6 s on: ${left.toFixed(4)} m there, ${leak.toExponential(2)} m in the right half`);
    expect(leak).toBeLessThan(0.01 * left);
    // The right-hand ring's front: the outermost crest stands near c t (the wave equation's ring trails behind its front).
    const front = waveFrontRadius(6, WAVE_EQUATION_SPEED);
    let outer = 0;
    for (let r = 2; r < 20; r += 0.05)
      if (
        grid.sample(28 + r, 0) > 0.02 * 0.4 &&
        grid.sample(28 + r, 0) >= grid.sample(28 + r + 0.05, 0) &&
        grid.sample(28 + r, 0) > grid.sample(28 + r - 0.05, 0)
      )
        outer = r;
    console.log(
      `Wave equation at c = ${WAVE_EQUATION_SPEED.toFixed(2)} m/s: outermost crest ${outer.toFixed(2)} m at 6 s, c t = ${front.toFixed(2)} m`,
    );
    expect(Math.abs(outer - front)).toBeLessThan(2);
  }, 120_000);
});

describe('determinism and obstacles', () => {
  it('gives bit-identical fields for the same disturbances at the same steps; another stone differs', () => {
    const run = (x: number) => {
      const grid = new IWaveGrid({ n: 48, spacing, kernel: fitted, damping: 0.05, sponge: { width: 8, strength: 4 } });
      for (let s = 0; s < 60; s++) {
        if (s === 0) grid.disturb({ x, z: 1, radius: 1, height: 0.3 });
        if (s === 20) grid.disturb({ x: -2, z: -1.5, radius: 0.8, height: -0.1 });
        grid.step(1 / 60);
      }
      return grid.height;
    };
    expect(Array.from(run(2))).toEqual(Array.from(run(2)));
    expect(Array.from(run(2.5))).not.toEqual(Array.from(run(2)));
  });

  it('keeps an obstacle dry and reflects from it: the water in front of a wall differs from open water', () => {
    const make = (wall: boolean) => {
      const n = 64;
      const grid = new IWaveGrid({ n, spacing, kernel: fitted, sponge: { width: 12, strength: 4 } });
      if (wall) for (let j = 0; j < n; j++) for (let i = 40; i < 43; i++) grid.obstacle[j * n + i] = 0;
      grid.disturb({ x: 0, z: 0, radius: 1, height: 0.2 });
      for (let s = 0; s < 240; s++) grid.step(1 / 30);
      return grid;
    };
    const walled = make(true);
    const open = make(false);
    const n = 64;
    let wet = 0;
    for (let j = 0; j < n; j++) for (let i = 40; i < 43; i++) wet = Math.max(wet, Math.abs(walled.height[j * n + i]));
    expect(wet).toBe(0);
    // In front of the wall (x from 1 to 3.5 m) the reflected waves add to what passes.
    let difference = 0;
    let scale = 0;
    for (let j = 20; j < 44; j++) {
      for (let i = 34; i < 39; i++) {
        difference = Math.max(difference, Math.abs(walled.height[j * n + i] - open.height[j * n + i]));
        scale = Math.max(scale, Math.abs(open.height[j * n + i]));
      }
    }
    expect(difference).toBeGreaterThan(0.3 * scale);
  });
});

/**
 * The largest share of a plane wave packet's amplitude that comes back from the border: a
 * channel 256 m long and 4 texels wide (z wraps round) with the border at +x, against the same
 * packet in a channel three times as long with no border; their difference inside the water
 * before the border is the reflection, divided by the free packet's amplitude at that moment.
 */
function borderReflection(k0: number, sponge: SpongeLayer | undefined): number {
  const dt = 1 / 20;
  const rows = 4;
  const width = sponge?.width ?? 0;
  const bordered = new IWaveGrid({ n: 512, rows, spacing, kernel: fitted, wrap: 'z', spongeAxes: 'x', sponge });
  const free = new IWaveGrid({ n: 1536, rows, spacing, kernel: fitted, wrap: 'xz' });
  const omega = (k: number) => Math.sqrt((g * kernelResponse(fitted, k * spacing, 0)) / spacing);
  const groupVelocity = (omega(k0 + 1e-4) - omega(k0 - 1e-4)) / 2e-4;
  const spread = (2 * Math.PI) / k0;
  const edge = 128 - width * spacing;
  const start = edge - 4 * spread;
  const envelope = (x: number) => Math.exp(-0.5 * ((x - start) / spread) ** 2);
  // Heading +x: one step earlier the packet stood a step back and its phase a step behind.
  for (const grid of [bordered, free]) {
    for (let j = 0; j < rows; j++) {
      for (let i = 0; i < grid.n; i++) {
        const x = grid.texelX(i);
        grid.height[j * grid.n + i] = envelope(x) * Math.cos(k0 * x);
        grid.previous[j * grid.n + i] = envelope(x + groupVelocity * dt) * Math.cos(k0 * x + omega(k0) * dt);
      }
    }
  }
  const offset = (free.n - bordered.n) / 2;
  let worst = 0;
  for (let t = 0; t < (2 * (128 - start) + 4 * spread) / groupVelocity; t += dt) {
    bordered.step(dt);
    free.step(dt);
    let incident = 0;
    for (let i = 0; i < free.n; i++) incident = Math.max(incident, Math.abs(free.height[i]));
    let back = 0;
    for (let i = 0; i < bordered.n; i++) {
      const x = bordered.texelX(i);
      if (x < edge - 2 && x > start - 4 * spread) back = Math.max(back, Math.abs(bordered.height[i] - free.height[i + offset]));
    }
    worst = Math.max(worst, back / incident);
  }
  return worst;
}

describe('the absorbing border', () => {
  // Planted fault: no sponge, the edge reflects.
  it("reflects at most 5 % of a wave packet's amplitude from 0.6 to 4 rad/m", () => {
    const reflections = [0.6, 1, 2, 4].map((k) => borderReflection(k, IWAVE_SPONGE));
    console.log(
      `Sponge (${IWAVE_SPONGE.width} texels, ${IWAVE_SPONGE.strength}/s): reflection ${reflections.map((r) => `${(100 * r).toFixed(2)} %`).join(', ')} at k = 0.6, 1, 2, 4 rad/m`,
    );
    for (const r of reflections) expect(r).toBeLessThan(0.05);
    const bare = borderReflection(1, undefined);
    console.log(`No sponge: reflection ${(100 * bare).toFixed(0)} % at k = 1 rad/m`);
    expect(bare).toBeGreaterThan(0.5);
  }, 120_000);
});
