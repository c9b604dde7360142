// `npm start` and `npm test` must work on a fresh clone: install dependencies when
// node_modules is missing or older than the manifest, and do nothing otherwise. The lock
// file lists every platform's packages, so `npm ci` reproduces it exactly anywhere.
// A node_modules that is a link (one install shared by several checkouts) is left alone:
// `npm ci` would empty the folder it points to, under every checkout that shares it.
import { existsSync, lstatSync, statSync } from 'node:fs';
import { execSync } from 'node:child_process';

const marker = 'node_modules/.package-lock.json';
const manifests = ['package.json', 'package-lock.json'].filter((f) => existsSync(f));
const stale = !existsSync(marker) || manifests.some((f) => statSync(f).mtimeMs > statSync(marker).mtimeMs);
const shared = lstatSync('node_modules', { throwIfNoEntry: false })?.isSymbolicLink() === true;

if (stale && shared) {
  console.log(
    '[oceano] node_modules is a link to a shared install: not reinstalling it here (run `npm ci` where it points if it is out of date)',
  );
} else if (stale) {
  const command = existsSync('package-lock.json') ? 'npm ci --no-audit --no-fund' : 'npm install --no-audit --no-fund';
  console.log(`[oceano] dependencies missing or out of date: running ${command}`);
  execSync(command, { stdio: 'inherit' });
}
