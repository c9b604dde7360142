import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { fixtureBundle } from './fixtureBundle';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { BROWSER_ARGS } from './harness';
import { findBrowser } from './harness';
import { InverseFft2d } from '../../src/sim/waves/fft/fft2d';
import { FftOcean } from '../../src/sim/waves/fft/fftOcean';
import { seededRandom } from '../../src/sim/noise/integerHash';
import { DEFAULT_SEA_STATE, type SeaState } from '../../src/sim/waves/spectra/seaState';
import type { FftParityApi } from './fixtures/fftParity';

/**
 * The GPU FFT (render targets, Stockham passes, float32) against fft.js (float64) on the CPU:
 * impulses, single modes, seeded random spectra, and the whole spectral ocean against its CPU twin.
 * The page is a bundle of tests/browser/fixtures/fftParity.ts on about:blank.
 */
let browser: Browser;
let page: Page;

beforeAll(async () => {
  const code = await fixtureBundle('fftParity');
  browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  page = await browser.newPage();
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.setContent('<!doctype html><html><body></body></html>');
  await page.addScriptTag({ content: code, type: 'module' });
  await page.waitForFunction(() => 'fftParity' in window, { timeout: 60_000 });
  expect(errors).toEqual([]);
}, 300_000);

afterAll(async () => {
  await browser?.close();
});

const gpu = <K extends keyof FftParityApi>(name: K, ...args: Parameters<FftParityApi[K]>): Promise<ReturnType<FftParityApi[K]>> =>
  page.evaluate(
    (n, a) => (window as unknown as { fftParity: Record<string, (...x: unknown[]) => unknown> }).fftParity[n](...a),
    name,
    args as unknown[],
  ) as Promise<ReturnType<FftParityApi[K]>>;

/** fft.js reference for the packed layout: RGBA texel = two complex numbers; inverse, unnormalised. */
function cpuInverse(n: number, input: number[]): number[] {
  const fft = new InverseFft2d(n);
  const out = new Array<number>(4 * n * n);
  for (const half of [0, 1]) {
    const c = new Float64Array(2 * n * n);
    for (let i = 0; i < n * n; i++) {
      c[2 * i] = input[4 * i + 2 * half];
      c[2 * i + 1] = input[4 * i + 2 * half + 1];
    }
    fft.transform(c);
    for (let i = 0; i < n * n; i++) {
      out[4 * i + 2 * half] = c[2 * i];
      out[4 * i + 2 * half + 1] = c[2 * i + 1];
    }
  }
  return out;
}

function relativeError(got: ArrayLike<number>, want: ArrayLike<number>): number {
  let diff = 0;
  let scale = 0;
  for (let i = 0; i < want.length; i++) {
    diff = Math.max(diff, Math.abs(got[i] - want[i]));
    scale = Math.max(scale, Math.abs(want[i]));
  }
  return diff / scale;
}

type Case = { name: string; input: (n: number) => [number[], number[]] };
const zeros = (n: number) => new Array<number>(4 * n * n).fill(0);
const cases: Case[] = [
  {
    name: 'impulses (→ single plane waves)',
    input: (n) => {
      const a = zeros(n);
      const b = zeros(n);
      a[4 * (3 * n + 5)] = 1; // mode (5, 3), real
      a[4 * (0 * n + 0) + 3] = 0.5; // DC of the second signal, imaginary
      b[4 * ((n - 1) * n + 2) + 1] = -2; // mode (2, −1)
      b[4 * ((n / 2) * n + n / 2) + 2] = 1; // the Nyquist corner
      return [a, b];
    },
  },
  {
    name: 'single modes (→ impulses)',
    input: (n) => {
      const a = zeros(n);
      const b = zeros(n);
      for (let q = 0; q < n; q++) {
        for (let p = 0; p < n; p++) {
          const phase = (-2 * Math.PI * (7 * p + 2 * q)) / n;
          a[4 * (q * n + p)] = Math.cos(phase);
          a[4 * (q * n + p) + 1] = Math.sin(phase);
          b[4 * (q * n + p) + 2] = Math.cos((-2 * Math.PI * (n - 1) * q) / n);
          b[4 * (q * n + p) + 3] = Math.sin((-2 * Math.PI * (n - 1) * q) / n);
        }
      }
      return [a, b];
    },
  },
  {
    name: 'seeded random spectra',
    input: (n) => {
      const r = seededRandom(n * 7 + 1);
      return [zeros(n).map(() => r() - 0.5), zeros(n).map(() => r() - 0.5)];
    },
  },
];

describe('GPU FFT against fft.js', () => {
  for (const n of [64, 128, 256]) {
    for (const c of cases) {
      it(`${c.name}, n = ${n}: within 1e-4 relative (planted fault: transposed reference fails)`, async () => {
        const [a, b] = c.input(n);
        const [ga, gb] = await gpu('inverse', n, a, b);
        const wantA = cpuInverse(n, a);
        const wantB = cpuInverse(n, b);
        const errors = [relativeError(ga, wantA), relativeError(gb, wantB)];
        console.log(`GPU FFT ${c.name} n=${n}: relative error ${errors.map((e) => e.toExponential(2)).join(', ')}`);
        for (const e of errors) expect(e).toBeLessThan(1e-4);
        // negative control: the reference with x and z swapped
        const transposed = wantA.map((_, i) => {
          const t = Math.floor(i / 4);
          const p = t % n;
          const q = Math.floor(t / n);
          return wantA[4 * (p * n + q) + (i % 4)];
        });
        expect(relativeError(ga, transposed)).toBeGreaterThan(1e-2);
      });
    }
  }
});

describe('GPU FFT stages: radix 4 and radix 2', () => {
  // The passes run radix 4 wherever it fits (stockhamRadices); the radix-2 stage runs alone for
  // odd log₂n (128 = 2·4³), so here the radix-2 pass is also checked on its own, every stage.
  for (const radices of [
    [2, 2, 2, 2, 2, 2, 2],
    [4, 4, 4, 2],
  ]) {
    it(`seeded random spectra, n = 128, stages ${radices.join(', ')}: within 1e-4 relative`, async () => {
      const n = 128;
      const [a, b] = cases[cases.length - 1].input(n);
      const [ga, gb] = await gpu('inverse', n, a, b, radices);
      const errors = [relativeError(ga, cpuInverse(n, a)), relativeError(gb, cpuInverse(n, b))];
      console.log(`GPU FFT stages ${radices.join(', ')}: relative error ${errors.map((e) => e.toExponential(2)).join(', ')}`);
      for (const e of errors) expect(e).toBeLessThan(1e-4);
    });
  }
});

describe('GPU FFT atlas: several grids in one set of passes', () => {
  // Three different grids side by side (the cascades' layout): each tile's result against fft.js
  // of that tile alone, so a stage that strayed into a neighbouring tile would mix in its signal.
  const n = 64;
  const tileInputs = [0, 1, 2].map((t): [number[], number[]] => {
    const r = seededRandom(1000 + t);
    return [zeros(n).map(() => r() - 0.5), zeros(n).map(() => r() - 0.5)];
  });
  const errorsOf = (outputs: [number[], number[]][], wanted: number[]) =>
    outputs.map(([ga, gb], i) => [
      relativeError(ga, cpuInverse(n, tileInputs[wanted[i]][0])),
      relativeError(gb, cpuInverse(n, tileInputs[wanted[i]][1])),
    ]);

  it('three seeded random tiles, n = 64: each tile within 1e-4 relative of its own CPU FFT', async () => {
    const outputs = await gpu('atlas', n, tileInputs, [0, 1, 2]);
    const errors = errorsOf(outputs, [0, 1, 2]);
    console.log(`GPU FFT atlas: relative errors per tile ${errors.map((e) => e.map((x) => x.toExponential(2)).join(', ')).join(' | ')}`);
    for (const e of errors.flat()) expect(e).toBeLessThan(1e-4);
  });

  it('planted fault: a wrong tile offset in the last stage (tile 1 read for tile 0) fails against tile 0', async () => {
    const outputs = await gpu('atlas', n, tileInputs, [1, 1, 2]);
    const errors = errorsOf(outputs, [0, 1, 2]);
    expect(Math.min(...errors[0])).toBeGreaterThan(1e-1);
    for (const e of [...errors[1], ...errors[2]]) expect(e).toBeLessThan(1e-4);
  });
});

describe('GPU spectral ocean against its CPU twin', () => {
  for (const [name, sea] of [
    ['fresh breeze, PM, 64²', { ...DEFAULT_SEA_STATE, fftSize: 64, windSpeed: 10 }],
    ['gale, 128²', { ...DEFAULT_SEA_STATE, fftSize: 128, windSpeed: 20, seed: 5 }],
    ['short fetch JONSWAP, 256²', { ...DEFAULT_SEA_STATE, fftSize: 256, windSpeed: 20, spectrum: 'jonswap', fetch: 20_000, seed: 9 }],
  ] as [string, SeaState][]) {
    // The fields within 1e-4 relative.
    it(`${name}: every texel of every cascade within 1 mm, at t = 10 s and t = 10⁶ + 3.7 s`, async () => {
      const times = [10, 1e6 + 3.7];
      const gpuFields = await gpu('ocean', sea, times);
      const cpu = new FftOcean(sea);
      times.forEach((t, ti) => {
        cpu.setTime(t);
        cpu.fields.forEach((f, c) => {
          const [displacement, derivatives] = gpuFields[ti][c];
          let mm = 0;
          for (let i = 0; i < displacement.length; i++) mm = Math.max(mm, Math.abs(displacement[i] - f.displacement[i]));
          const rel = [relativeError(displacement, f.displacement), relativeError(derivatives, f.derivatives)];
          console.log(
            `${name} t=${t} cascade ${c}: max |Δ| ${(mm * 1000).toFixed(4)} mm, relative ${rel.map((e) => e.toExponential(2)).join(', ')}`,
          );
          expect(mm).toBeLessThan(1e-3);
          for (const e of rel) expect(e).toBeLessThan(1e-4);
        });
      });
      // planted fault: the CPU twin 0.05 s later is not the GPU's sea
      cpu.setTime(times[0] + 0.05);
      expect(relativeError(gpuFields[0][0][0], cpu.fields[0].displacement)).toBeGreaterThan(1e-3);
    });
  }

  it('the lattice tile (cascade 2 at a time of its own) within 1 mm, riding with the frame and alone', async () => {
    const sea: SeaState = { ...DEFAULT_SEA_STATE, fftSize: 128, windSpeed: 20, seed: 5 };
    const [time, latticeTime] = [1e6 + 3.7, 1e6 + 3.6];
    const { riding, alone } = await gpu('lattice', sea, 2, time, latticeTime);
    const cpu = new FftOcean(sea);
    cpu.setTime(latticeTime);
    const want = cpu.fields[2];
    for (const [displacement, derivatives] of [riding, alone]) {
      let mm = 0;
      for (let i = 0; i < displacement.length; i++) mm = Math.max(mm, Math.abs(displacement[i] - want.displacement[i]));
      console.log(`lattice tile: max |Δ| ${(mm * 1000).toFixed(4)} mm`);
      expect(mm).toBeLessThan(1e-3);
      expect(relativeError(derivatives, want.derivatives)).toBeLessThan(1e-4);
    }
    // planted fault: the frame's time is not the lattice time
    cpu.setTime(time);
    expect(relativeError(riding[0], cpu.fields[2].displacement)).toBeGreaterThan(1e-3);
  });

  it('reports the GPU FFT cost on this renderer (3 cascades, one update)', async () => {
    for (const fftSize of [64, 128, 256] as const) {
      const ms = await gpu('cost', { ...DEFAULT_SEA_STATE, fftSize }, fftSize === 256 ? 5 : 10);
      console.log(`GPU FFT ocean update, 3 cascades, ${fftSize}²: ${ms.toFixed(1)} ms`);
      expect(ms).toBeGreaterThan(0);
    }
  });
});
