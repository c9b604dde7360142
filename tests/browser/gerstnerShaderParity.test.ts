import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { withNativeSine } from '../support/nativeSine';
import puppeteer, { type Browser } from 'puppeteer';
import { readFileSync } from 'node:fs';
import { BROWSER_ARGS } from './harness';
import { findBrowser } from './harness';
import { gerstnerSea } from '../../src/sim/waves/gerstner/gerstnerSpectrum';
import { GerstnerWaveModel, gerstnerTimePhases } from '../../src/sim/waves/gerstner/gerstnerWaves';
import { seededRandom } from '../../src/sim/noise/integerHash';
import { cosineSquared, piersonMoskowitz } from '../support/testSeas';

/**
 * shaders/waves/gerstner.glsl against its CPU twin, on SwiftShader's WebGL2, before the chunk is
 * wired into the ocean: the chunk's waveDisplacement and waveNormal run in a bare vertex
 * shader whose outputs are captured by transform feedback, on float32 points up to 3 km
 * out and times up to 10⁶ s. Needs no build and no app page (about:blank).
 */
const shaderFile = (path: string) => readFileSync(new URL(`../../shaders/${path}`, import.meta.url), 'utf8');
// The chunk with its one include resolved as three.js resolves it in the app.
const CHUNK = shaderFile('waves/gerstner.glsl').replace('#include <oceano_sin_turns>', shaderFile('sinTurns.glsl'));
const PARITY_SEED = 20261121;
const TIMES = [0, 37.25, 100_000.125, 987_654.3];

/** Runs in the page: compiles the chunk, evaluates it at the points, returns [dx, dy, dz, nx, ny, nz] per point. */
const EVALUATE = `(chunk, waves, phases, points, count) => {
  const gl = document.createElement('canvas').getContext('webgl2');
  const vs = '#version 300 es\\nprecision highp float;\\nprecision highp int;\\n' + chunk +
    '\\nin vec2 grid;\\nout vec3 disp;\\nout vec3 nrm;\\nvoid main() { disp = waveDisplacement(grid); nrm = waveNormal(grid); gl_Position = vec4(0.0); }';
  // The fragment stage gets the chunk too: ocean.frag evaluates waveNormal per pixel, and the
  // fragment stage has fewer uniform vectors (WebGL2 promises 224) than the vertex stage.
  const fs = '#version 300 es\\nprecision highp float;\\nprecision highp int;\\n' + chunk +
    '\\nout vec4 colour;\\nvoid main() { colour = vec4(waveNormal(gl_FragCoord.xy), 1.0); }';
  function compile(type, source) {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  }
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl.VERTEX_SHADER, vs));
  gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fs));
  gl.transformFeedbackVaryings(program, ['disp', 'nrm'], gl.INTERLEAVED_ATTRIBS);
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
  gl.useProgram(program);
  gl.uniform1i(gl.getUniformLocation(program, 'uGerstnerCount'), count);
  const table = new Float32Array(256);
  table.set(waves);
  gl.uniform4fv(gl.getUniformLocation(program, 'uGerstnerWaves[0]'), table);
  const tau = new Float32Array(64);
  tau.set(phases);
  gl.uniform4fv(gl.getUniformLocation(program, 'uGerstnerPhases[0]'), tau);
  const input = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, input);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(points.flat()), gl.STATIC_DRAW);
  const at = gl.getAttribLocation(program, 'grid');
  gl.enableVertexAttribArray(at);
  gl.vertexAttribPointer(at, 2, gl.FLOAT, false, 0, 0);
  const output = gl.createBuffer();
  gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, output);
  gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, points.length * 24, gl.STREAM_READ);
  gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, output);
  gl.enable(gl.RASTERIZER_DISCARD);
  gl.beginTransformFeedback(gl.POINTS);
  gl.drawArrays(gl.POINTS, 0, points.length);
  gl.endTransformFeedback();
  const result = new Float32Array(points.length * 6);
  gl.getBufferSubData(gl.TRANSFORM_FEEDBACK_BUFFER, 0, result);
  return Array.from(result);
}`;

let browser: Browser;
beforeAll(async () => {
  browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
});
afterAll(async () => {
  await browser?.close();
});

/** Worst |Δ| of displacement and normal components over all times and points. */
async function parity(chunk: string): Promise<{ displacement: number; normal: number }> {
  const sea = gerstnerSea({
    count: 64,
    seed: 7,
    spectrum: piersonMoskowitz(15).spectrum,
    spreading: cosineSquared,
    windDirection: 0.5,
    steepness: 1,
  });
  const model = new GerstnerWaveModel(sea);
  const random = seededRandom(PARITY_SEED);
  // float32 points, as every ocean vertex is, so both sides evaluate the same (x, z).
  const points = Array.from({ length: 512 }, () => [Math.fround((random() * 2 - 1) * 3000), Math.fround((random() * 2 - 1) * 3000)]);
  const waves = sea.flatMap((w) => [w.cx, w.cz, w.amplitude, w.horizontal]);
  const page = await browser.newPage();
  let displacement = 0;
  let normal = 0;
  for (const t of TIMES) {
    const phases = Array.from(gerstnerTimePhases(sea, t));
    const call = `(${EVALUATE})(${JSON.stringify(chunk)}, ${JSON.stringify(waves)}, ${JSON.stringify(phases)}, ${JSON.stringify(points)}, ${sea.length})`;
    const gpu = (await page.evaluate(call)) as number[];
    points.forEach(([x, z], i) => {
      const d = model.displacement(x, z, t);
      const n = model.normal(x, z, t);
      for (let c = 0; c < 3; c++) {
        displacement = Math.max(displacement, Math.abs(d[c] - gpu[6 * i + c]));
        normal = Math.max(normal, Math.abs(n[c] - gpu[6 * i + 3 + c]));
      }
    });
  }
  await page.close();
  return { displacement, normal };
}

describe('Gerstner GLSL chunk vs CPU twin (SwiftShader, transform feedback)', () => {
  it(`agrees within 1e-4 m on 512 points (seed ${PARITY_SEED}) up to 3 km out, t up to 1e6 s, 64 waves at Q = 1`, async () => {
    const worst = await parity(CHUNK);
    console.log(
      `[oceano] Gerstner GLSL parity: max |Δd| = ${worst.displacement.toExponential(2)} m, max |Δn| = ${worst.normal.toExponential(2)}`,
    );
    // Measured 2.4e-5 m and 2.6e-6 (sea of Hs ≈ 5 m).
    expect(worst.displacement).toBeLessThan(1e-4);
    expect(worst.normal).toBeLessThan(1e-4);
  }, 120_000);

  it("negative control: GLSL's own sin (about 2^-11 accurate on SwiftShader) breaks the 1e-4 m budget", async () => {
    const native = withNativeSine(CHUNK);
    // Measured 5.8e-4 m.
    expect((await parity(native)).displacement).toBeGreaterThan(1e-4);
  }, 120_000);
});
