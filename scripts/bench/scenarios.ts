import type { Page } from 'puppeteer';

/**
 * What the benchmark measures: each scenario is one row of the results, drawn in a page
 * of its own. To add a row (brute-force grid against LOD, the underwater passes, the boat),
 * add one entry here: a URL query that fixes `t` so every run draws the same picture, and,
 * when the URL is not enough, a setup step run after `oceano.ready` and before the timing.
 * The first scenario is the headline: its figures are the top-level ones in the JSON, and
 * its ttffMs is the app's first load (empty caches); later rows load with warm caches.
 */
export interface BenchScenario {
  name: string;
  query: string;
  /** Which page draws it: Oceano (the default) or the copy of three.js's ocean example. */
  page?: 'oceano' | 'threejs-ocean';
  setup?: (page: Page) => Promise<void>;
  /** Timed frames when the default count would take too long (the brute-force grid). */
  frames?: number;
  /** Also time each render pass separately (oceano.debug.passTimings). */
  passes?: boolean;
  /**
   * Seconds the clock moves between timed frames (from the query's `t`), for a sea whose frame
   * does per-time GPU work (waves=fft: the FFT and foam passes). Unset: the clock stays paused,
   * and a model that caches its work per time would skip it.
   */
  stepSeconds?: number;
  /** Also measure the wave twin's main-thread ms per frame with the clock playing (loopTwinMs). */
  twin?: boolean;
}

export const SCENARIOS: readonly BenchScenario[] = [
  { name: 'default view', query: 't=10' },
  // The comparison teachers make: three.js's own ocean example, drawn in the same browser.
  { name: 'three.js ocean example (Water + Sky + bloom)', query: '', page: 'threejs-ocean' },
  { name: 'three.js ocean example (Water + Sky, no bloom)', query: 'bloom=0', page: 'threejs-ocean' },
  // The same eye as the default view, turned up (mostly sky) and down (sea fills the frame).
  { name: 'looking up', query: 't=10&cam=0,9,40,0,60,-20' },
  { name: 'looking down', query: 't=10&cam=0,9,40,0,0,30' },
  // The LOD's reference: every chunk of the same 4 km extent at full resolution, no culling.
  { name: 'brute-force grid, same extent', query: 't=10&lodBruteForce=1', frames: 3 },
  { name: 'underwater (Snell window, god rays, blur)', query: 't=10&preset=underwater', passes: true },
  // The library's default underwater path: a half-float scene target, no material patched (OceanUnderwater).
  {
    name: 'underwater, half-float scene target (library default)',
    query: 't=10&preset=underwater',
    passes: true,
    setup: async (page) => {
      await page.evaluate(async () => {
        await window.oceano.debug.underwaterScene('linear');
        window.oceano.renderFrame();
        await window.oceano.loaded();
      });
    },
  },
  // The spectral sea (issue 12) from the default camera: its frame with the clock running at
  // 60 Hz (every frame evolves the spectra, runs the FFTs and one foam step), and those
  // passes timed alone.
  { name: 'FFT view (waves=fft, clock running)', query: 't=10&waves=fft', passes: true, stepSeconds: 1 / 60, twin: true },
  // What each new term of the light costs, the FFT view without it (docs/light.md).
  { name: 'FFT view, foam as paint (foamTexture=0)', query: 't=10&waves=fft&foamTexture=0', stepSeconds: 1 / 60 },
  { name: 'FFT view, no subsurface glow (subsurface=0)', query: 't=10&waves=fft&subsurface=0', stepSeconds: 1 / 60 },
  { name: 'FFT view, no roughness (seaRoughness=0)', query: 't=10&waves=fft&seaRoughness=0', stepSeconds: 1 / 60 },
  { name: 'FFT view, sharp sky (skyBlur=0)', query: 't=10&waves=fft&skyBlur=0', stepSeconds: 1 / 60 },
  { name: 'FFT view, no wave groups (waveGroups=0)', query: 't=10&waves=fft&waveGroups=0', stepSeconds: 1 / 60 },
  { name: 'default view, sharp sky (skyBlur=0)', query: 't=10&skyBlur=0' },
  // The windrows are compiled in only from Beaufort 7 (13.9 m/s): the gale pays for them, the FFT view does not.
  { name: 'gale (preset=gale, clock running)', query: 't=10&preset=gale', stepSeconds: 1 / 60 },
  { name: 'gale, no windrows (windrows=0)', query: 't=10&preset=gale&windrows=0', stepSeconds: 1 / 60 },
  // The three models side by side against the dearest of them alone, same camera
  // and wind, both with the clock running (the FFT passes run in both).
  // Each strip's render is timed apart ('scene <model> strip'), to see where a split frame's time goes.
  { name: 'compare-models (seed | gerstner | fft)', query: 't=10&preset=compare-models', passes: true, stepSeconds: 1 / 60 },
  {
    name: 'compare-models camera, fft alone',
    query: 't=10&preset=compare-models&compare=off&waves=fft',
    passes: true,
    stepSeconds: 1 / 60,
  },
  // The other candidate for the dearest model: 32 trochoids, the long ones summed per vertex, the short ones per pixel.
  {
    name: 'compare-models camera, gerstner alone',
    query: 't=10&preset=compare-models&compare=off&waves=gerstner',
    passes: true,
    stepSeconds: 1 / 60,
  },
  // The default view with the interactive waves on, the clock at 60 Hz so each frame
  // steps the field once (its step pass, the read-back for sampleSurface, the field in the
  // ocean's shaders); a stone in it, so the picture has waves to draw.
  {
    name: 'interactive waves on, default view (field stepped at 60 Hz)',
    query: 't=10&interactiveWaves=1&stones=10,0,-20,1,0.5',
    stepSeconds: 1 / 60,
  },
  // Every model at most 2× the seed's frame from the same camera.
  { name: 'compare-models camera, seed alone', query: 't=10&preset=compare-models&compare=off&waves=seed', stepSeconds: 1 / 60 },
  // The steepest Gerstner lesson (4 trochoids at Q = 1, 1.2 m above the water).
  { name: 'gerstner-steepness', query: 't=10&preset=gerstner-steepness', stepSeconds: 1 / 60 },
  // The coast: the beach preset from its sand (the swell's field, the land, the surf and the shallows' colour).
  { name: 'beach view (preset=beach)', query: 't=10&preset=beach' },
];

/** The ratios the targets are stated in: [label, numerator scenario, denominator scenario or 'floor', target]. */
export const COMPARISONS: readonly [string, string, string, number | null][] = [
  ['default / three.js example (Water + Sky, no bloom)', 'default view', 'three.js ocean example (Water + Sky, no bloom)', 0.6],
  ['default / three.js example (Water + Sky + bloom)', 'default view', 'three.js ocean example (Water + Sky + bloom)', 0.6],
  ['default / floor', 'default view', 'floor', 20],
  ['underwater / default', 'underwater (Snell window, god rays, blur)', 'default view', 2],
  [
    'underwater half-float / encoded',
    'underwater, half-float scene target (library default)',
    'underwater (Snell window, god rays, blur)',
    null,
  ],
  // The spectral sea at most 1.3× the seed's frame, same camera, same run.
  ['FFT view / default', 'FFT view (waves=fft, clock running)', 'default view', 1.3],
  ['FFT view / foam as paint', 'FFT view (waves=fft, clock running)', 'FFT view, foam as paint (foamTexture=0)', null],
  ['FFT view / no subsurface glow', 'FFT view (waves=fft, clock running)', 'FFT view, no subsurface glow (subsurface=0)', null],
  ['FFT view / no roughness', 'FFT view (waves=fft, clock running)', 'FFT view, no roughness (seaRoughness=0)', null],
  ['FFT view / sharp sky', 'FFT view (waves=fft, clock running)', 'FFT view, sharp sky (skyBlur=0)', null],
  ['FFT view / no wave groups', 'FFT view (waves=fft, clock running)', 'FFT view, no wave groups (waveGroups=0)', null],
  ['default / sharp sky', 'default view', 'default view, sharp sky (skyBlur=0)', null],
  ['gale / no windrows', 'gale (preset=gale, clock running)', 'gale, no windrows (windrows=0)', null],
  // A split view costs no more than its dearest model alone.
  ['compare-models / fft alone', 'compare-models (seed | gerstner | fft)', 'compare-models camera, fft alone', 1],
  ['compare-models / gerstner alone', 'compare-models (seed | gerstner | fft)', 'compare-models camera, gerstner alone', 1],
  // The interactive waves cost at most 15 % more than the default view without them.
  ['interactive waves / default', 'interactive waves on, default view (field stepped at 60 Hz)', 'default view', 1.15],
  // Each wave model at most 2× the seed's frame, at the compare-models camera.
  ['gerstner alone / seed alone (compare-models camera)', 'compare-models camera, gerstner alone', 'compare-models camera, seed alone', 2],
  ['fft alone / seed alone (compare-models camera)', 'compare-models camera, fft alone', 'compare-models camera, seed alone', 2],
  // The beach view at most 1.5× the default view.
  ['beach / default', 'beach view (preset=beach)', 'default view', 1.5],
  ['looking up / default', 'looking up', 'default view', null],
  ['looking down / default', 'looking down', 'default view', null],
];
