#!/bin/bash
# Runs on the lent GPU machine, from the repository's root (docs/performance.md, "On a real GPU"):
# joins the browser's two halves (.gpu1 came in the first call and was kept in /root/keep),
# installs the Vulkan layer ANGLE needs there, and times Oceano. FRAMES and ROUNDS as gpu_frames.py, SIZES the canvases.
set -u -o pipefail
C=/tmp/chr
mkdir -p $C /tmp/vklayer /etc/vulkan/implicit_layer.d /tmp/glroot
A=/root/keep/chromium.xz.aa; [ -f $A ] || A=.gpu1/chromium.xz.aa
python3 - "$A" .gpu2/chromium.xz.ab $C <<'PY' || { echo "unpacking the browser failed"; exit 3; }
import lzma, os, sys, tarfile
first, second, target = sys.argv[1:4]
with open(f'{target}/chromium', 'wb') as out:
    out.write(lzma.decompress(open(first, 'rb').read() + open(second, 'rb').read()))
os.chmod(f'{target}/chromium', 0o755)
tarfile.open('.gpu2/chrome-libs.tar.xz').extractall(target)
PY
# Not on a machine without the GPU (DRY_RUN_SOFTWARE): the layer would stay in its Vulkan set-up.
[ -n "${DRY_RUN_SOFTWARE:-}" ] || { cp .gpu2/liboceano_headless.so /tmp/vklayer/ && cp .gpu2/headlessSurfaceLayer.json /etc/vulkan/implicit_layer.d/; }
for deb in .gpu2/gl/*.deb; do dpkg -x "$deb" /tmp/glroot; done
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
# Each canvas size (SIZES, e.g. "1920x1080 3840x2160") in a folder of its own; screenshots only at the first,
# since at most 8 files come back from a call.
first=1
for size in ${SIZES:-1920x1080}; do
  mkdir -p "$OUT/$size"
  SIZE=$size SHOTS=$first PYTHONUNBUFFERED=1 python3 .gpu2/gpu_frames.py $C .gpu2/site "$OUT/$size" "${ROUNDS:-8}" 2>&1 | tee "$OUT/$size/log.txt" ||
    cat /tmp/chrome-93*.log 2>/dev/null | grep -v ReadPixels | tail -c 300000 > "$OUT/chrome.log"
  first=
done
