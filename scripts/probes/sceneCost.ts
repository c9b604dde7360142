// Where the frame goes: times the view with each top-level scene object hidden in turn
// and each child of a group (interleaved rounds, medians of 7 frames), so each object's cost reads as a difference in
// one page. Usage: npx vite build && npx tsx scripts/probes/sceneCost.ts ["query"] [rounds] [WxH]
import { openOcean, startHarness } from '../../tests/browser/harness';

const query = process.argv[2] ?? 't=10';
const rounds = Number(process.argv[3] ?? 4);
const [width, height] = (process.argv[4] ?? '1280x720').split('x').map(Number);

// Runs in the page. Kept as a string: tsx would wrap named arrows in a helper the page lacks.
const inPage = `(() => {
  const o = window.oceano;
  const name = (c, i) => i + ':' + (c.name || c.type) + ':' + ((c.material && c.material.type) || '');
  const objects = o.three.scene.children.flatMap((c, i) => [{ c, label: name(c, i) }, ...(c.type === 'Group' ? c.children.map((g, j) => ({ c: g, label: '  ' + name(c, i) + '/' + name(g, j) })) : [])]);
  const time = (frames) => {
    const ts = [];
    for (let i = 0; i < frames; i++) { const s = performance.now(); o.renderFrame(); ts.push(performance.now() - s); }
    ts.sort((a, b) => a - b);
    return ts[Math.floor(frames / 2)];
  };
  const samples = { all: [] };
  for (const { label } of objects) samples[label] = [];
  time(3);
  for (let r = 0; r < ${rounds}; r++) {
    samples.all.push(time(7));
    for (const { c, label } of objects) { const was = c.visible; c.visible = false; samples[label].push(time(7)); c.visible = was; }
  }
  // The same frame with only one pixel rasterised: what is left is per-vertex and per-draw work.
  const renderer = o.three.renderer;
  samples.onePixel = [];
  samples.onePixelNoSea = [];
  const sea = o.three.scene.getObjectByName('oceano-ocean');
  for (let r = 0; r < ${rounds}; r++) {
    renderer.setScissorTest(true); renderer.setScissor(0, 0, 1, 1);
    samples.onePixel.push(time(7));
    sea.visible = false; samples.onePixelNoSea.push(time(7)); sea.visible = true;
    renderer.setScissorTest(false);
  }
  // Lower bounds. trivialOcean: the sea's pixels write a constant (its vertices, triangles and
  // depth test unchanged). floor: everything hidden but the sky's screen-covering triangle,
  // itself given a constant colour: the bench's floor (clear + full-screen quad), in this page.
  const TRIVIAL = 'void main() { gl_FragColor = vec4(0.2, 0.4, 0.6, 1.0); }';
  const swap = (material, fragment) => { const was = material.fragmentShader; material.fragmentShader = fragment; material.needsUpdate = true; return was; };
  const found = new Set();
  sea.traverse((c) => { if (c.material && c.material.uniforms && c.material.uniforms.uEyeRelative) found.add(c.material); });
  const oceanMaterials = [...found];
  const sky = o.three.scene.getObjectByName('oceano-sky');
  samples.trivialOcean = [];
  samples.floor = [];
  for (let r = 0; r < ${rounds}; r++) {
    const kept = oceanMaterials.map((m) => swap(m, TRIVIAL));
    time(2);
    samples.trivialOcean.push(time(7));
    oceanMaterials.forEach((m, i) => swap(m, kept[i]));
    const shown = o.three.scene.children.map((c) => c.visible);
    o.three.scene.children.forEach((c) => { c.visible = c === sky; });
    const skyFragment = swap(sky.material, TRIVIAL);
    time(2);
    samples.floor.push(time(7));
    swap(sky.material, skyFragment);
    o.three.scene.children.forEach((c, i) => { c.visible = shown[i]; });
    time(2);
  }
  const med = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];
  return Object.fromEntries(Object.entries(samples).map(([k, v]) => [k, Math.round(med(v) * 10) / 10]));
})()`;

const harness = await startHarness();
const { page } = await openOcean(harness, query, width, height);
console.log(JSON.stringify(await page.evaluate(inPage), null, 1));
await harness.close();
