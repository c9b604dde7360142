#!/usr/bin/env bash
# Prepares, on this machine, what the lent GPU machine needs to time Oceano in headless Chromium
# (docs/performance.md, "On a real GPU"). That machine has Python but no Node.js, no browser and
# no network, and one call carries at most 64 MiB. So the browser (the headless shell that the
# npm package @sparticuz/chromium ships, 67 MB compressed) travels in two halves: .gpu1/ in a
# first call, .gpu2/ (the other half, the builds, the driver and the Vulkan layer) in a second.
# Usage: scripts/gpu/prepare.sh [BASE_COMMIT]   (the build to compare against; default 65d506c)
set -euo pipefail
cd "$(dirname "$0")/../.."
BASE=${1:-65d506c}
exclude=$(git rev-parse --git-path info/exclude)
mkdir -p "$(dirname "$exclude")"
for path in /.gpu1/ /.gpu2/; do grep -qxF "$path" "$exclude" 2>/dev/null || echo "$path" >> "$exclude"; done
rm -rf .gpu1 .gpu2
mkdir -p .gpu1 .gpu2/site
work=$(mktemp -d)
trap 'rm -rf "$work"; git worktree remove --force "$work-base" 2>/dev/null || true' EXIT

echo "[gpu] the browser"
(cd "$work" && npm pack --silent @sparticuz/chromium@153.0.0 >/dev/null && tar xzf sparticuz-chromium-*.tgz)
node -e '
const fs = require("fs"), zlib = require("zlib"), [bin, out] = process.argv.slice(1);
fs.writeFileSync(out + "/chromium", zlib.brotliDecompressSync(fs.readFileSync(bin + "/chromium.br")));
for (const name of ["al2023", "swiftshader", "fonts"])
  fs.writeFileSync(out + "/" + name + ".tar", zlib.brotliDecompressSync(fs.readFileSync(bin + "/" + name + ".tar.br")));
' "$work/package/bin" "$work"
mkdir -p "$work/libs"
for name in al2023 swiftshader fonts; do tar xf "$work/$name.tar" -C "$work/libs"; done
tar cJf .gpu2/chrome-libs.tar.xz -C "$work/libs" .
xz -T2 -9 -c "$work/chromium" | split -b 33000000 - "$work/chromium.xz."
mv "$work/chromium.xz.aa" .gpu1/
mv "$work/chromium.xz.ab" .gpu2/

echo "[gpu] the Vulkan layer"
[ -f /usr/include/vulkan/vk_layer.h ] || apt-get install -y -qq libvulkan-dev >/dev/null
gcc -O2 -shared -fPIC -fvisibility=hidden -o .gpu2/liboceano_headless.so scripts/gpu/headlessSurfaceLayer.c
mkdir -p .gpu2/gl
(cd .gpu2/gl && apt-get download -qq libglvnd0 libegl1 libgl1 libglx0 libgles2 libopengl0 2>/dev/null)
cp scripts/gpu/headlessSurfaceLayer.json scripts/gpu/gpu_frames.py scripts/gpu/run.sh .gpu2/

echo "[gpu] the builds: this one, $BASE, three.js's ocean example"
npx vite build --outDir .gpu2/site/now --emptyOutDir --logLevel error
node -e "require('vite').build({ configFile: false, root: 'scripts/bench/threejsOcean', base: './', logLevel: 'error',
  build: { outDir: process.cwd() + '/.gpu2/site/three', emptyOutDir: true, reportCompressedSize: false } })"
git worktree add -f "$work-base" "$BASE" >/dev/null 2>&1
ln -s "$PWD/node_modules" "$work-base/node_modules"
(cd "$work-base" && npx vite build --outDir "$OLDPWD/.gpu2/site/base" --emptyOutDir --logLevel error)
du -sh .gpu1 .gpu2
