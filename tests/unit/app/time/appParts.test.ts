import { afterEach, describe, expect, it, vi } from 'vitest';
import { FrameStats } from '../../../../src/app/time/frameStats';
import { FrameLoop } from '../../../../src/app/time/frameLoop';
import { paramsChanged } from '../../../../src/sim/params/paramChanges';
import { defaultParams } from '../../../../src/sim/params/params';
import type { RenderStats } from '../../../../src/render/ocean/oceanView';
import { shareUrl } from '../../../../src/app/url/sharing';
import { parseUrlState } from '../../../../src/app/url/urlState';
import type { BoatSnapshot } from '../../../../src/sim/boat/boatMotion';

const RENDER: RenderStats = {
  drawCalls: 2,
  triangles: 10,
  chunksTotal: 4,
  chunksVisible: 3,
  farCellsVisible: 5,
  lodCounts: [3],
  underwater: false,
  submersion: 'above',
  composerPasses: 0,
};

describe('FrameStats', () => {
  it('never stalls the shipped loop on the GPU until stats are asked for, then one frame in eight', () => {
    const stats = new FrameStats();
    const syncs = (frames: number) => {
      let n = 0;
      for (let i = 0; i < frames; i++) {
        if (stats.loopShouldSync()) n++;
        stats.framesDrawn++;
      }
      return n;
    };
    expect(syncs(64)).toBe(0);
    stats.summary(RENDER, null);
    expect(syncs(64)).toBe(8);
  });

  it('reports medians of the recorded samples (0 before any)', () => {
    const stats = new FrameStats();
    expect(stats.summary(RENDER, null)).toMatchObject({ frameMs: 0, cpuMs: 0, boatMs: 0, ttffMs: null, triangles: 10 });
    for (const ms of [5, 1, 3]) stats.recordUpdate(ms / 10, ms);
    stats.recordSyncedFrame(7);
    expect(stats.summary(RENDER, null)).toMatchObject({ frameMs: 7, cpuMs: 3, boatMs: 0.3 });
  });

  it("reports the wave twin's mean main-thread ms per frame, null where the model does not measure it", () => {
    const stats = new FrameStats();
    expect(stats.summary(RENDER, null).twinMs).toBeNull();
    for (const ms of [0, 0.1, 0, 0.3]) stats.recordTwin(ms);
    expect(stats.summary(RENDER, null).twinMs).toBeCloseTo(0.1, 12);
    // Switched to a model that does not measure it: no figure, rather than the old model's.
    stats.recordTwin(null);
    expect(stats.summary(RENDER, null).twinMs).toBeNull();
    const twin = { fieldsReceived: 3, fieldsTime: 10.05 };
    expect(stats.summary(RENDER, twin).twin).toEqual(twin);
  });
});

describe('paramsChanged', () => {
  it('sees a change only in the keys asked about; everything is new the first time', () => {
    const a = defaultParams();
    const b = { ...a, boatHeading: a.boatHeading + 1 };
    expect(paramsChanged(null, a, ['blurStrength'])).toBe(true);
    expect(paramsChanged(a, b, ['blurStrength', 'godRays'])).toBe(false);
    expect(paramsChanged(a, b, ['blurStrength', 'boatHeading'])).toBe(true);
  });
});

describe('FrameLoop', () => {
  afterEach(() => vi.unstubAllGlobals());

  it('runs only when started, playing and not stopped for any reason', () => {
    const frames: FrameRequestCallback[] = [];
    vi.stubGlobal('requestAnimationFrame', (cb: FrameRequestCallback) => frames.push(cb));
    vi.stubGlobal('cancelAnimationFrame', () => {});
    let playing = true;
    const loop = new FrameLoop({ tick: () => {}, redraw: () => {}, playing: () => playing });
    expect(loop.isLooping).toBe(false);
    loop.start();
    expect(loop.isLooping).toBe(true);
    loop.setStopped('hidden', true);
    loop.setStopped('contextLost', true);
    loop.setStopped('hidden', false);
    expect(loop.isLooping).toBe(false);
    loop.setStopped('contextLost', false);
    expect(loop.isLooping).toBe(true);
    playing = false;
    loop.refresh();
    expect(loop.isLooping).toBe(false);
    // A paused view draws once on request, and only one frame however often it is asked.
    const before = frames.length;
    loop.requestRender();
    loop.requestRender();
    expect(frames.length).toBe(before + 1);
    loop.dispose();
    expect(loop.isLooping).toBe(false);
  });
});

describe('shareUrl', () => {
  it("carries the view, the boat's motion at its time and the page's choices, and reads back as they were", () => {
    const params = { ...defaultParams(), boatSpeed: 2.4, boatHeading: 30 };
    // Values with full double precision, so a link that rounds any of them shows.
    const boatState: BoatSnapshot = {
      x: 6.361234567891,
      z: -5.33,
      heading: { value: 0.1 / 3, velocity: -0.2 },
      heave: { value: 1 / 7, velocity: 0.01 },
      pitch: { value: -0.02, velocity: 1e-5 },
      roll: { value: 0.03, velocity: -2e-4 },
    };
    const camera = { position: [10, 4, 12] as [number, number, number], target: [0, 0, 0] as [number, number, number] };
    const page = {
      shareBase: 'https://example.org/ocean/',
      language: 'es' as const,
      state: { sky: 'skies/dusk', boat: 'models/b.glb', embed: true },
    };
    const url = shareUrl(page, { params, time: 3.25, camera, boatState });
    expect(url.startsWith('https://example.org/ocean/?')).toBe(true);
    const back = parseUrlState(url.slice(url.indexOf('?')));
    expect(back.notices).toEqual([]);
    expect(back).toMatchObject({ time: 3.25, camera, boatState, language: 'es', sky: 'skies/dusk', boat: 'models/b.glb', embed: true });
    expect(back.params).toEqual(params);
    // Without a state (the boat last floated at another time) the link lets it start afresh.
    expect(parseUrlState(shareUrl(page, { params, time: 3.25, camera, boatState: null }).split('?')[1]).boatState).toBeNull();
  });
});
