// `npm test`: the type check, the unit tests and the production build at the same time, then
// the browser tests against that build. The type check (about 28 s) and the build (about 18 s)
// finish long before the unit tests, so the unit tests get a worker per core (vitest's default
// is one fewer than the cores: one worker on this 2-core machine, 100 s beside the other two;
// two workers, 61 s, 13:27 UTC quiet). The unit tests never read dist/, so building while they
// run changes nothing they see. The browser tests start only once all three have passed, and
// have the machine to themselves.
import { spawn } from 'node:child_process';
import { availableParallelism } from 'node:os';

/** Runs a command; its output is kept and printed whole when it ends, unless `live`. */
function run(label, command, args, live = false) {
  return new Promise((resolve) => {
    const started = Date.now();
    const child = spawn(command, args, { stdio: live ? 'inherit' : ['ignore', 'pipe', 'pipe'], shell: process.platform === 'win32' });
    const output = [];
    if (!live) {
      child.stdout.on('data', (chunk) => output.push(chunk));
      child.stderr.on('data', (chunk) => output.push(chunk));
    }
    child.on('close', (code, signal) => {
      const seconds = ((Date.now() - started) / 1000).toFixed(1);
      if (!live) process.stdout.write(`\n[oceano] ${label}:\n${Buffer.concat(output).toString()}`);
      console.log(`[oceano] ${label}: ${code === 0 ? 'passed' : `failed (${signal ?? `exit ${code}`})`} in ${seconds} s`);
      resolve(code === 0);
    });
  });
}

const npx = process.platform === 'win32' ? 'npx.cmd' : 'npx';
const first = await Promise.all([
  run('unit tests', npx, ['vitest', 'run', '--project', 'unit', `--maxWorkers=${Math.max(2, availableParallelism())}`], true),
  run('type check (tsc --noEmit)', npx, ['tsc', '--noEmit']),
  run('build (vite build)', npx, ['vite', 'build']),
]);
if (first.includes(false)) process.exit(1);
const browserFound = await run('browser check', process.execPath, ['tests/browser/ensure-browser.mjs'], true);
if (!browserFound) process.exit(1);
process.exit((await run('browser tests', npx, ['vitest', 'run', '--project', 'browser'], true)) ? 0 : 1);
