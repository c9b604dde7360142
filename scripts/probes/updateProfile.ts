/**
 * Where the app's update step goes (stats().cpuMs): a sampling CPU profile (Chrome DevTools
 * protocol, 25 µs interval) of `frames` paused frames drawn by renderFrame, reduced to the
 * subtree of the given entry functions, with self and total time per function in it, per
 * frame. Needs an unminified build for readable names:
 *   npx vite build --minify false --outDir dist/prof
 *   npx tsx scripts/probes/updateProfile.ts prof [frames] [query] [entry,entry]
 * A profiler's figures are estimates (sampling, and the profiler's own overhead): use it to
 * find the parts, and the bench's cpuMs (oceano.stats().cpuMs) to measure the whole.
 */
import { openOcean, startHarness } from '../../tests/browser/harness';

const build = process.argv[2] ?? 'prof';
const frames = Number(process.argv[3] ?? 300);
const query = process.argv[4] ?? 't=10';
const entries = (process.argv[5] ?? 'update').split(',');

interface ProfileNode {
  id: number;
  callFrame: { functionName: string; url: string; lineNumber: number };
  children?: number[];
}
interface Profile {
  nodes: ProfileNode[];
  samples: number[];
  timeDeltas: number[];
}

const harness = await startHarness();
try {
  const { page } = await openOcean(harness, query, 640, 360, `${build}/`, 600_000);
  await page.evaluate(`(() => { const o = window.oceano; o.pause(); for (let i = 0; i < 30; i++) o.renderFrame(); })()`);
  const session = await page.createCDPSession();
  await session.send('Profiler.enable');
  await session.send('Profiler.setSamplingInterval', { interval: 25 });
  await session.send('Profiler.start');
  await page.evaluate(`(() => { const o = window.oceano; for (let i = 0; i < ${frames}; i++) o.renderFrame(); })()`);
  const { profile } = (await session.send('Profiler.stop')) as unknown as { profile: Profile };
  const byId = new Map(profile.nodes.map((n) => [n.id, n]));
  const parent = new Map<number, number>();
  for (const n of profile.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
  const name = (n: ProfileNode) =>
    `${n.callFrame.functionName || '(anon)'} ${n.callFrame.url.split('/').pop()}:${n.callFrame.lineNumber + 1}`;
  // Each sample's time (the delta to the next sample is the time it stands for).
  const self = new Map<string, number>();
  const total = new Map<string, number>();
  let inEntry = 0;
  profile.samples.forEach((id, i) => {
    const dt = (profile.timeDeltas[i + 1] ?? 0) / 1000;
    const stack: ProfileNode[] = [];
    for (let n: number | undefined = id; n !== undefined; n = parent.get(n)) stack.push(byId.get(n) as ProfileNode);
    // A function called by renderFrame itself whose name is an entry (its two update calls).
    // (the innermost renderFrame: the API's renderFrame calls the app's).
    const frameAt = stack.findIndex((n) => n.callFrame.functionName === 'renderFrame');
    const entryAt = frameAt - 1;
    if (frameAt < 1 || !entries.includes(stack[entryAt].callFrame.functionName)) return;
    inEntry += dt;
    const inside = stack.slice(0, entryAt + 1);
    self.set(name(inside[0]), (self.get(name(inside[0])) ?? 0) + dt);
    for (const key of new Set(inside.map(name))) total.set(key, (total.get(key) ?? 0) + dt);
  });
  const perFrame = (ms: number) => ((ms / frames) * 1000).toFixed(1).padStart(7);
  console.log(`${query}, ${frames} paused frames: inside [${entries.join(', ')}] ${perFrame(inEntry)} µs per frame (sampled)`);
  console.log('total µs/frame, self µs/frame, function');
  for (const [key, ms] of [...total].sort((a, b) => b[1] - a[1]).slice(0, 45))
    console.log(`${perFrame(ms)} ${perFrame(self.get(key) ?? 0)}  ${key}`);
} finally {
  await harness.close();
}
