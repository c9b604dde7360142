// What each part of the ocean's pixel shader costs: the ocean materials' fragment shader is
// edited in the page (text replacements, recompiled), one variant at a time, and the frame
// timed; rounds go round the variants so a drifting load moves them alike. Medians of 7
// frames per round, then the median over rounds. Prints figures, asserts nothing.
// Usage: npx vite build && npx tsx scripts/probes/shaderVariants.ts VARIANTS.json ["query"] [rounds]
// PROBE_STAGE=vertex edits the vertex shader instead; PROBE_ONE_PIXEL=1 times every frame with
// a 1×1 scissor, so what is left is the vertices' and the draws' work.
// VARIANTS.json: { "name": [["text to find", "replacement"], ...], ... } (a missing text is an error).
import { readFileSync } from 'node:fs';
import { openOcean, startHarness } from '../../tests/browser/harness';

const variants = JSON.parse(readFileSync(process.argv[2], 'utf8')) as Record<string, [string, string][]>;
const query = process.argv[3] ?? 't=10';
const rounds = Number(process.argv[4] ?? 5);
const stage = process.env.PROBE_STAGE === 'vertex' ? 'vertexShader' : 'fragmentShader';
const onePixel = process.env.PROBE_ONE_PIXEL === '1';

// Runs in the page. A string: tsx would wrap named arrows in a helper the page lacks.
const inPage = `(() => {
  const o = window.oceano;
  const variants = ${JSON.stringify(variants)};
  // The ocean's materials: every mesh's material with the ocean's uniforms (uEyeRelative).
  const found = new Set();
  o.three.scene.traverse((c) => { if (c.material && c.material.uniforms && c.material.uniforms.uEyeRelative) found.add(c.material); });
  const materials = [...found];
  const originals = materials.map((m) => m.${stage});
  if (${onePixel}) { o.three.renderer.setScissorTest(true); o.three.renderer.setScissor(0, 0, 1, 1); }
  const time = (frames) => {
    const ts = [];
    for (let i = 0; i < frames; i++) { const s = performance.now(); o.renderFrame(); ts.push(performance.now() - s); }
    ts.sort((a, b) => a - b);
    return ts[Math.floor(frames / 2)];
  };
  const apply = (edits) => materials.forEach((m, i) => {
    let text = originals[i];
    for (const [from, to] of edits) {
      if (!text.includes(from)) throw new Error('not in the shader: ' + from);
      text = text.split(from).join(to);
    }
    m.${stage} = text;
    m.needsUpdate = true;
  });
  const names = ['base', ...Object.keys(variants)];
  const samples = Object.fromEntries(names.map((n) => [n, []]));
  for (let r = 0; r < ${rounds}; r++) {
    for (const name of names) {
      apply(name === 'base' ? [] : variants[name]);
      time(2);
      samples[name].push(time(7));
    }
  }
  apply([]);
  o.three.renderer.setScissorTest(false);
  const med = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];
  return Object.fromEntries(names.map((n) => [n, Math.round(med(samples[n]) * 10) / 10]));
})()`;

const harness = await startHarness();
const { page } = await openOcean(harness, query, 1280, 720);
console.log(JSON.stringify(await page.evaluate(inPage), null, 1));
await harness.close();
