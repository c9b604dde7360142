// `npm start` and `npm test` must work on a fresh clone: install dependencies when
// node_modules is missing or older than the manifest, and do nothing otherwise.
import { existsSync, statSync } from 'node:fs';
import { execSync } from 'node:child_process';

const marker = 'node_modules/.package-lock.json';
const manifests = ['package.json', 'package-lock.json'].filter((f) => existsSync(f));
const stale =
  !existsSync(marker) || manifests.some((f) => statSync(f).mtimeMs > statSync(marker).mtimeMs);

if (stale) {
  // `npm install` rather than `npm ci`: the lock file written here may list only this
  // platform's optional packages, which `npm ci` refuses on another machine.
  const command = 'npm install --no-audit --no-fund';
  console.log(`[oceano] dependencies missing or out of date: running ${command}`);
  execSync(command, { stdio: 'inherit' });
}
