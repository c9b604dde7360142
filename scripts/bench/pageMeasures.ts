/**
 * Measurements that run inside the page (passed to puppeteer's page.evaluate, so each is
 * self-contained: no imports, and no named functions inside, which tsx's bundler would
 * wrap in a `__name` helper that the page does not have). Every timed frame
 * ends with a one-pixel readPixels, which waits for the GPU, so GPU work is counted.
 */

export interface OceanFrames {
  frameTimes: number[];
  /** From oceano.stats(): median update step of the app's last 30 frames, all of them timed ones. */
  cpuMs: number;
  drawCalls: number;
  triangles: number;
  ttffMs: number | null;
  canvas: [number, number];
}

/**
 * Times `frames` synced frames of the ocean, clock paused, after `warmup` untimed ones. With
 * `stepSeconds` > 0 the paused clock, from `startTime` (the query's t), is moved on by that much
 * before every frame (warm-up included), as a playing clock would: what the frame costs when time moves.
 */
export function timeOceanFrames(frames: number, warmup: number, stepSeconds = 0, startTime = 0): OceanFrames {
  const oceano = window.oceano;
  oceano.pause();
  // No helper function for the step: tsx would wrap a named one in a `__name` the page lacks.
  for (let i = 0; i < warmup; i++) {
    if (stepSeconds > 0) oceano.setTime(startTime + (i + 1) * stepSeconds);
    oceano.renderFrame();
  }
  const frameTimes: number[] = [];
  for (let i = 0; i < frames; i++) {
    if (stepSeconds > 0) oceano.setTime(startTime + (warmup + i + 1) * stepSeconds);
    const start = performance.now();
    oceano.renderFrame();
    frameTimes.push(performance.now() - start);
  }
  const stats = oceano.stats();
  const canvas = oceano.three.renderer.domElement;
  return {
    frameTimes,
    cpuMs: stats.cpuMs,
    drawCalls: stats.drawCalls,
    triangles: stats.triangles,
    ttffMs: stats.ttffMs,
    canvas: [canvas.width, canvas.height],
  };
}

/**
 * The wave model's CPU twin's main-thread ms per frame (oceano.stats().twinMs) with the clock
 * playing in the app's own frame loop, so the Worker's replies arrive between frames as on a
 * live page (the timed frames above run in one task: no reply can arrive). Waits for
 * `frames` looped frames (the stats' window), then pauses. null where the model does not measure it.
 */
export async function loopTwinMs(frames: number): Promise<number | null> {
  const oceano = window.oceano;
  const first = oceano.activity().framesDrawn;
  oceano.play();
  // No named helper (see above): an anonymous interval callback.
  await new Promise<void>((resolve) => {
    const timer = setInterval(() => {
      if (oceano.activity().framesDrawn - first < frames) return;
      clearInterval(timer);
      resolve();
    }, 50);
  });
  oceano.pause();
  return oceano.stats().twinMs;
}

export interface FloorFrames {
  frameTimes: number[];
  renderer: string;
}

/**
 * The cost floor of a frame on this machine: a clear and one full-screen quad with a
 * constant-colour shader, in raw WebGL2 on a canvas of the ocean's size, synced the same way.
 */
export function timeFloorFrames(width: number, height: number, frames: number, warmup: number): FloorFrames {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
  if (!gl) throw new Error('No WebGL2 context for the floor measurement.');
  const program = gl.createProgram() as WebGLProgram;
  // Four corners from gl_VertexID, drawn as a strip: no buffers, nothing but the quad.
  const sources: [number, string][] = [
    [
      gl.VERTEX_SHADER,
      '#version 300 es\nvoid main() { vec2 p = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0; gl_Position = vec4(p, 0.0, 1.0); }',
    ],
    [gl.FRAGMENT_SHADER, '#version 300 es\nprecision mediump float; out vec4 color; void main() { color = vec4(0.04, 0.18, 0.27, 1.0); }'],
  ];
  for (const [type, source] of sources) {
    const shader = gl.createShader(type) as WebGLShader;
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`Floor shader: ${gl.getShaderInfoLog(shader)}`);
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`Floor program: ${gl.getProgramInfoLog(program)}`);
  gl.useProgram(program);
  gl.viewport(0, 0, width, height);
  const pixel = new Uint8Array(4);
  const frameTimes: number[] = [];
  for (let i = 0; i < warmup + frames; i++) {
    const start = performance.now();
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    if (i >= warmup) frameTimes.push(performance.now() - start);
  }
  const debugInfo = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = String(gl.getParameter(debugInfo ? debugInfo.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return { frameTimes, renderer };
}

/** The WebGL renderer string and whether fine-grained timers are on (cross-origin isolation). */
export function pageEnvironment(): { renderer: string; crossOriginIsolated: boolean } {
  const gl = window.oceano.three.renderer.getContext();
  const debugInfo = gl.getExtension('WEBGL_debug_renderer_info');
  return {
    renderer: String(gl.getParameter(debugInfo ? debugInfo.UNMASKED_RENDERER_WEBGL : gl.RENDERER)),
    crossOriginIsolated: window.crossOriginIsolated,
  };
}

/**
 * Runs in the page: profiles `frames` frames with oceano.debug.passTimings() (each pass
 * followed by a GPU sync) and returns each pass's times, ms. Serialised into the page, so
 * it imports nothing: bench.ts takes each pass's median in node.
 */
export async function passTimeSamples(frames: number): Promise<Record<string, number[]>> {
  const samples: Record<string, number[]> = {};
  for (let i = 0; i < frames; i++) {
    for (const { name, ms } of await window.oceano.debug.passTimings()) (samples[name] ??= []).push(ms);
  }
  return samples;
}

export interface ExampleFrames {
  frameTimes: number[];
  drawCalls: number;
  triangles: number;
  canvas: [number, number];
}

/** Times `frames` frames of three.js's ocean example page after `warmup` untimed ones, each ended by a one-pixel readPixels. */
export function timeThreejsExampleFrames(frames: number, warmup: number): ExampleFrames {
  const example = window.threejsOcean;
  for (let i = 0; i < warmup; i++) example.renderFrame();
  const frameTimes: number[] = [];
  for (let i = 0; i < frames; i++) {
    const start = performance.now();
    example.renderFrame();
    frameTimes.push(performance.now() - start);
  }
  const stats = example.stats();
  return { frameTimes, drawCalls: stats.drawCalls, triangles: stats.triangles, canvas: example.canvas() };
}
