/**
 * Prints what the spectral sea's CPU twin costs (a benchmark: numbers, no assertions):
 * setTime (time evolution + 4 inverse FFTs per cascade, once per time step; a Worker's job if
 * it is too slow for the main thread) and sample() (the boat's per-frame reads).
 * Run: npx tsx scripts/fftCost.ts
 */
import { FftOcean } from '../src/sim/waves/fft/fftOcean';
import { DEFAULT_SEA_STATE } from '../src/sim/waves/spectra/seaState';

for (const fftSize of [64, 128, 256] as const) {
  const ocean = new FftOcean({ ...DEFAULT_SEA_STATE, fftSize });
  ocean.setTime(0);
  const steps = fftSize === 256 ? 3 : 6;
  let start = performance.now();
  for (let i = 1; i <= steps; i++) ocean.setTime(i / 60);
  const setTime = (performance.now() - start) / steps;
  // Five samples per frame (the boat's hull points), 2000 frames, time fixed as within a frame.
  let sink = 0;
  for (let i = 0; i < 200; i++) sink += ocean.sample(i, i, 1).height; // warm-up
  start = performance.now();
  const frames = 2000;
  for (let f = 0; f < frames; f++) for (let s = 0; s < 5; s++) sink += ocean.sample(f * 0.37 + s, f * 0.11 - s, steps / 60).height;
  const perFrame = (performance.now() - start) / frames;
  console.log(`fftSize ${fftSize}: setTime ${setTime.toFixed(1)} ms, 5 × sample() ${(perFrame * 1000).toFixed(1)} µs per frame (${sink.toFixed(0)})`);
}
