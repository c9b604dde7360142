import { mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { join } from 'node:path';
import puppeteer from 'puppeteer';
import { BROWSER_ARGS, findBrowser, startHarness } from './browserHarness';
import { cpuByKind } from './procCpu';

/**
 * What each GPU pipeline of the first frame costs SwiftShader to build (issue 14's ttffMs).
 * SwiftShader compiles a program's pipeline to machine code on its first draw, not at link,
 * so the cost of a program is the GPU process's CPU time over its first draw.
 *
 *   npx tsx scripts/compileProbe.ts capture [query] [dir]
 *     loads the built app (dist/, 1280x720) and writes into dir (default /tmp/compileProbe)
 *     the vertex and fragment sources of every program the first frame draws with, in draw
 *     order (NN.vert, NN.frag), as WebGL received them from three.js.
 *   npx tsx scripts/compileProbe.ts measure [rounds] dir...
 *     for each NN.vert / NN.frag pair in each dir, a fresh Chromium (its GPU process started
 *     by a blank page first, as ttffProbe does) links the pair and draws one triangle into a
 *     1x1 canvas: GPU-process CPU ms for the link and for the first draw (plus readPixels),
 *     and for a second draw (what is not compilation). Median of `rounds` browsers,
 *     interleaved across the dirs, so variants of one shader compare in one run.
 */

const mode = process.argv[2];

if (mode === 'capture') {
  const query = process.argv[3] ?? 't=10';
  const dir = process.argv[4] ?? '/tmp/compileProbe';
  mkdirSync(dir, { recursive: true });
  // Each draw of the first frame is followed by a one-pixel read (which waits for the GPU
  // process) and a synchronous request here, which reads the GPU process's CPU time: the
  // cost of each draw, its pipeline's compile included.
  let root = 0;
  let last = 0;
  const costs: string[] = [];
  const server = createServer((request, response) => {
    const gpu = cpuByKind(root).gpu;
    costs.push(`${decodeURIComponent((request.url ?? '').slice(1)).padEnd(48)} GPU CPU +${gpu - last} ms`);
    last = gpu;
    response.writeHead(204, { 'access-control-allow-origin': '*' });
    response.end();
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const url = `http://127.0.0.1:${(server.address() as AddressInfo).port}/`;
  const harness = await startHarness(BROWSER_ARGS);
  try {
    root = harness.browser.process()?.pid ?? 0;
    const warm = await harness.browser.newPage();
    await warm.evaluate(() => document.createElement('canvas').getContext('webgl2') !== null);
    await warm.close();
    const page = await harness.browser.newPage();
    await page.setBypassCSP(true);
    await page.setViewport({ width: 1280, height: 720, deviceScaleFactor: 1 });
    page.setDefaultTimeout(300_000);
    // A string, not a function: tsx would wrap named helpers in a `__name` the page lacks.
    await page.evaluateOnNewDocument(`(() => {
      const P = WebGL2RenderingContext.prototype;
      const sources = new Map();
      const programs = new Map();
      let current = null;
      let frameDone = false;
      const draws = [];
      window.__probe = { draws, programs };
      const report = (what) => {
        const request = new XMLHttpRequest();
        request.open('GET', ${JSON.stringify(url)} + encodeURIComponent(what), false);
        request.send();
      };
      const shaderSource = P.shaderSource;
      P.shaderSource = function (shader, source) { sources.set(shader, source); return shaderSource.call(this, shader, source); };
      const attachShader = P.attachShader;
      P.attachShader = function (program, shader) {
        const entry = programs.get(program) ?? { vert: '', frag: '', id: programs.size };
        const source = sources.get(shader) ?? '';
        if (this.getShaderParameter(shader, this.SHADER_TYPE) === this.VERTEX_SHADER) entry.vert = source; else entry.frag = source;
        programs.set(program, entry);
        return attachShader.call(this, program, shader);
      };
      const useProgram = P.useProgram;
      P.useProgram = function (program) { current = program; return useProgram.call(this, program); };
      for (const name of ['drawArrays', 'drawElements', 'drawArraysInstanced', 'drawElementsInstanced', 'drawRangeElements']) {
        const original = P[name];
        P[name] = function (...args) {
          if (frameDone || !current) return original.apply(this, args);
          draws.push({ program: programs.get(current).id, call: name, t: performance.now() });
          const px = new Uint8Array(4);
          this.readPixels(0, 0, 1, 1, this.RGBA, this.UNSIGNED_BYTE, px);
          report('before program ' + programs.get(current).id + ' ' + name + ' ' + args.join(','));
          const result = original.apply(this, args);
          this.readPixels(0, 0, 1, 1, this.RGBA, this.UNSIGNED_BYTE, px);
          report('program ' + programs.get(current).id + ' ' + name + ' ' + args.join(','));
          return result;
        };
      }
      // Other calls between the marks, each timed the same way (the one-pixel read first, so a
      // call is charged only with its own work).
      for (const name of ['texImage2D', 'texSubImage2D', 'texStorage2D', 'generateMipmap', 'linkProgram', 'getProgramParameter', 'clear', 'compileShader', 'bindFramebuffer', 'blitFramebuffer', 'getUniformLocation']) {
        const original = P[name];
        P[name] = function (...args) {
          if (frameDone || !window.__measure) return original.apply(this, args);
          const px = new Uint8Array(4);
          window.__measure = false;
          this.readPixels(0, 0, 1, 1, this.RGBA, this.UNSIGNED_BYTE, px);
          report('before ' + name);
          const result = original.apply(this, args);
          this.readPixels(0, 0, 1, 1, this.RGBA, this.UNSIGNED_BYTE, px);
          report(name + ' ' + args.filter((a) => typeof a === 'number').join(','));
          window.__measure = true;
          return result;
        };
      }
      const mark = performance.mark.bind(performance);
      performance.mark = (name, options) => {
        if (name === 'oceano:first-draw-submitted') { frameDone = true; draws.push({ program: -1, call: name, t: performance.now() }); }
        if (name === 'oceano:first-update') window.__measure = true;
        if (name.startsWith('oceano:')) { draws.push({ program: -2, call: name, t: performance.now() }); report(name); }
        return mark(name, options);
      };
    })()`);
    await page.goto(`${harness.baseUrl}${process.env.PROBE_BUILD ? `${process.env.PROBE_BUILD}/` : ""}?${query}`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    const captured = (await page.evaluate(`(() => ({ draws: window.__probe.draws, programs: [...window.__probe.programs.values()] }))()`)) as {
      draws: { program: number; call: string; t: number }[];
      programs: { id: number; vert: string; frag: string }[];
    };
    const order: number[] = [];
    for (const draw of captured.draws) {
      console.log(`${draw.t.toFixed(0).padStart(6)}  ${draw.program < 0 ? draw.call : `program ${draw.program} ${draw.call}`}`);
      if (draw.program >= 0 && !order.includes(draw.program)) order.push(draw.program);
    }
    order.forEach((id, index) => {
      const program = captured.programs.find((p) => p.id === id)!;
      const name = String(index).padStart(2, '0');
      writeFileSync(join(dir, `${name}.vert`), program.vert);
      writeFileSync(join(dir, `${name}.frag`), program.frag);
      const firstLine = (source: string) => source.split('\n').find((l) => l.startsWith('#define SHADER_NAME')) ?? '';
      console.log(`${name}: program ${id}, ${program.vert.length} + ${program.frag.length} chars ${firstLine(program.vert)} ${firstLine(program.frag)}`);
    });
    for (const line of costs) console.log(line);
  } finally {
    await harness.close();
    server.close();
  }
} else if (mode === 'measure') {
  const rounds = Number(process.argv[3] ?? 3);
  const dirs = process.argv.slice(4);
  const pairs = dirs.flatMap((dir) =>
    readdirSync(dir)
      .filter((f) => f.endsWith('.vert'))
      .sort()
      .map((f) => ({ label: `${dir}/${f.slice(0, -5)}`, vert: readFileSync(join(dir, f), 'utf8'), frag: readFileSync(join(dir, f.replace(/\.vert$/, '.frag')), 'utf8') })),
  );
  const results = new Map<string, { link: number; first: number; second: number }[]>(pairs.map((p) => [p.label, []]));
  const executablePath = await findBrowser();
  // SEQUENCE=1: each dir's pairs drawn one after another in one browser (does a later
  // program reuse what an earlier one compiled?).
  const sequence = process.env.SEQUENCE === '1';
  const groups = sequence ? dirs.map((dir) => pairs.filter((p) => p.label.startsWith(`${dir}/`))) : pairs.map((p) => [p]);
  for (let round = 0; round < rounds; round++) {
    for (const group of groups) {
      const browser = await puppeteer.launch({ executablePath, args: BROWSER_ARGS, headless: true, protocolTimeout: 600_000 });
      try {
        const root = browser.process()?.pid ?? 0;
        const page = await browser.newPage();
        await page.evaluate(() => document.createElement('canvas').getContext('webgl2') !== null);
        for (const pair of group) {
        // Set up the context first, so what is measured is this pair's own cost.
        if (!(await page.evaluate('window.__gl !== undefined'))) await page.evaluate(`(() => {
          const canvas = document.createElement('canvas');
          canvas.width = 1; canvas.height = 1;
          document.body.appendChild(canvas);
          const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
          window.__gl = gl;
          const px = new Uint8Array(4);
          gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
        })()`);
        const step = async (code: string) => {
          const before = cpuByKind(root).gpu;
          await page.evaluate(code);
          return cpuByKind(root).gpu - before;
        };
        const link = await step(`(() => {
          const gl = window.__gl;
          const compile = (type, source) => { const s = gl.createShader(type); gl.shaderSource(s, source); gl.compileShader(s); if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s)); return s; };
          const program = gl.createProgram();
          gl.attachShader(program, compile(gl.VERTEX_SHADER, ${JSON.stringify(pair.vert)}));
          gl.attachShader(program, compile(gl.FRAGMENT_SHADER, ${JSON.stringify(pair.frag)}));
          gl.linkProgram(program);
          if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
          gl.useProgram(program);
          gl.bindVertexArray(gl.createVertexArray());
          // Each sampler on its own unit: two sampler types on one unit make the draw an error.
          const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
          let unit = 0;
          for (let i = 0; i < count; i++) {
            const info = gl.getActiveUniform(program, i);
            if (!/SAMPLER/.test(Object.keys(Object.getPrototypeOf(gl)).find((k) => gl[k] === info.type && /SAMPLER/.test(k)) ?? '')) continue;
            for (let j = 0; j < info.size; j++) gl.uniform1i(gl.getUniformLocation(program, info.size > 1 ? info.name.replace(/\[0\]$/, '[' + j + ']') : info.name), unit++);
          }
        })()`);
        const drawCode = `(() => {
          const gl = window.__gl;
          gl.drawArrays(gl.TRIANGLES, 0, 3);
          const px = new Uint8Array(4);
          gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
          const error = gl.getError();
          if (error !== gl.NO_ERROR) throw new Error('GL error ' + error);
        })()`;
        const first = await step(drawCode);
        const second = await step(drawCode);
        results.get(pair.label)!.push({ link, first, second });
        }
      } finally {
        await browser.close();
      }
    }
  }
  const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
  console.log('GPU-process CPU ms (median [each round]): link, first draw, second draw');
  for (const [label, runs] of results) {
    const show = (key: 'link' | 'first' | 'second') => `${String(median(runs.map((r) => r[key]))).padStart(5)} [${runs.map((r) => r[key]).join(' ')}]`;
    console.log(`${label.padEnd(40)} link ${show('link')}  first ${show('first')}  second ${show('second')}`);
  }
}
