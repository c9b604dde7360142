#!/usr/bin/env python3
"""Oceano's frame times on a lent GPU machine, in headless Chromium driven over CDP.

That machine has Python but no Node.js, so this is the benchmark's frame timing
(scripts/bench/pageMeasures.ts timeOceanFrames) again in Python's standard library alone.
Prepared by scripts/gpu/prepare.sh, run there by run.sh; docs/performance.md says how.

Usage: gpu_frames.py CHROME_DIR SITE_DIR OUT_DIR [ROUNDS]   (FRAMES=n sets the frames a round, SIZE=3840x2160 the canvas)
SITE_DIR holds now/ (this build), base/ (the build compared against) and three/ (three.js's ocean example).
DRY_RUN_SOFTWARE=1 runs it on SwiftShader, to check it on a machine without a GPU.
"""
import base64, glob, json, os, socket, statistics, struct, subprocess, sys, threading, time, urllib.request
import functools, http.server

CHROME_DIR, SITE_DIR, OUT = sys.argv[1], sys.argv[2], sys.argv[3]
ROUNDS = int(sys.argv[4]) if len(sys.argv) > 4 else 4
W, H = (int(v) for v in os.environ.get('SIZE', '1920x1080').split('x'))
FRAMES, WARMUP = int(os.environ.get('FRAMES', 40)), 8


class Handler(http.server.SimpleHTTPRequestHandler):
    def end_headers(self):
        self.send_header('Cross-Origin-Opener-Policy', 'same-origin')
        self.send_header('Cross-Origin-Embedder-Policy', 'require-corp')
        self.send_header('Cache-Control', 'no-store')
        super().end_headers()

    def log_message(self, *args):
        pass


def serve(root):
    server = http.server.ThreadingHTTPServer(('127.0.0.1', 0), functools.partial(Handler, directory=root))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return f'http://127.0.0.1:{server.server_address[1]}/'


class WebSocket:
    """The client half of RFC 6455, enough for CDP: text frames, masked sends, pings answered."""

    def __init__(self, url):
        hostport, path = url[len('ws://'):].split('/', 1)
        host, port = hostport.split(':')
        self.sock = socket.create_connection((host, int(port)), timeout=900)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall((f'GET /{path} HTTP/1.1\r\nHost: {hostport}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n'
                           f'Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n').encode())
        self.buf = bytearray()
        while b'\r\n\r\n' not in self.buf:
            self._fill()
        end = self.buf.index(b'\r\n\r\n')
        if b' 101 ' not in bytes(self.buf[:end]).split(b'\r\n')[0]:
            raise RuntimeError(f'WebSocket handshake refused: {bytes(self.buf[:end])!r}')
        del self.buf[:end + 4]

    def _fill(self):
        chunk = self.sock.recv(1 << 20)
        if not chunk:
            raise RuntimeError('CDP socket closed')
        self.buf += chunk

    def _take(self, n):
        while len(self.buf) < n:
            self._fill()
        out = bytes(self.buf[:n])
        del self.buf[:n]
        return out

    def _send_frame(self, opcode, payload):
        n = len(payload)
        head = bytearray([0x80 | opcode])
        if n < 126:
            head.append(0x80 | n)
        elif n < 65536:
            head += bytes([0x80 | 126]) + struct.pack('>H', n)
        else:
            head += bytes([0x80 | 127]) + struct.pack('>Q', n)
        mask = os.urandom(4)
        body = bytes(b ^ mask[i & 3] for i, b in enumerate(payload))
        self.sock.sendall(bytes(head) + mask + body)

    def send(self, text):
        self._send_frame(1, text.encode())

    def recv(self):
        message = bytearray()
        while True:
            b0, b1 = self._take(2)
            n = b1 & 0x7f
            if n == 126:
                n = struct.unpack('>H', self._take(2))[0]
            elif n == 127:
                n = struct.unpack('>Q', self._take(8))[0]
            mask = self._take(4) if b1 & 0x80 else None
            data = self._take(n)
            if mask:
                data = bytes(b ^ mask[i & 3] for i, b in enumerate(data))
            opcode = b0 & 0x0f
            if opcode == 9:
                self._send_frame(10, data)
                continue
            if opcode == 8:
                raise RuntimeError('CDP socket closed by the browser')
            message += data
            if b0 & 0x80 and opcode in (0, 1, 2):
                return message.decode()


class Page:
    def __init__(self, ws_url):
        self.ws = WebSocket(ws_url)
        self.next_id = 0
        self.errors = []
        self.call('Runtime.enable')
        self.call('Page.enable')
        self.call('Emulation.setDeviceMetricsOverride', width=W, height=H, deviceScaleFactor=1, mobile=False)

    def call(self, method, **params):
        self.next_id += 1
        my_id = self.next_id
        self.ws.send(json.dumps({'id': my_id, 'method': method, 'params': params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get('id') == my_id:
                if 'error' in msg:
                    raise RuntimeError(f'{method}: {msg["error"]}')
                return msg['result']
            method_in = msg.get('method')
            if method_in == 'Runtime.exceptionThrown':
                self.errors.append(msg['params']['exceptionDetails'].get('exception', {}).get('description', 'exception'))
            elif method_in == 'Runtime.consoleAPICalled' and msg['params']['type'] == 'error':
                self.errors.append(' '.join(str(a.get('value', a.get('description', ''))) for a in msg['params']['args']))

    def evaluate(self, expression):
        result = self.call('Runtime.evaluate', expression=expression, awaitPromise=True, returnByValue=True)
        if 'exceptionDetails' in result:
            raise RuntimeError(f'page threw: {json.dumps(result["exceptionDetails"])[:600]}')
        return result['result'].get('value')

    def goto(self, url, ready_expression, timeout=120):
        self.call('Page.navigate', url='about:blank')
        self.call('Page.navigate', url=url)
        deadline = time.time() + timeout
        while time.time() < deadline:
            if self.evaluate(f'location.href === {json.dumps(url)} && document.readyState === "complete" && ({ready_expression})'):
                return
            time.sleep(0.1)
        raise RuntimeError(f'{url} did not get ready in {timeout} s')

    def screenshot(self, path):
        data = self.call('Page.captureScreenshot', format='png')['data']
        with open(path, 'wb') as f:
            f.write(base64.b64decode(data))


RENDERER = '''(() => { const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return 'no WebGL2'; const info = gl.getExtension('WEBGL_debug_renderer_info');
  return gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER); })()'''

OCEAN_FRAMES = '''(async () => { const o = window.oceano; await o.ready; if (o.loaded) await o.loaded();
  o.pause(); const t0 = %(t0)s, step = %(step)s;
  for (let i = 0; i < %(warmup)d; i++) { if (step > 0) o.setTime(t0 + (i + 1) * step); o.renderFrame(); }
  const times = []; %(timer)s
  for (let i = 0; i < %(frames)d; i++) { if (step > 0) o.setTime(t0 + (%(warmup)d + i + 1) * step);
    const q = ext ? gl.createQuery() : null; if (q) gl.beginQuery(ext.TIME_ELAPSED_EXT, q);
    const s = performance.now(); o.renderFrame(); times.push(performance.now() - s);
    if (q) { gl.endQuery(ext.TIME_ELAPSED_EXT); queries.push(q); } }
  %(gpu)s
  const c = document.querySelector('canvas');
  const st = o.stats(); return { times, gpu, canvas: [c.width, c.height], drawCalls: st.drawCalls, cpuMs: st.cpuMs }; })()'''

EXAMPLE_FRAMES = '''(async () => { const e = window.threejsOcean; for (let i = 0; i < %(warmup)d; i++) e.renderFrame();
  const times = []; %(timer)s
  for (let i = 0; i < %(frames)d; i++) { const q = ext ? gl.createQuery() : null; if (q) gl.beginQuery(ext.TIME_ELAPSED_EXT, q);
    const s = performance.now(); e.renderFrame(); times.push(performance.now() - s);
    if (q) { gl.endQuery(ext.TIME_ELAPSED_EXT); queries.push(q); } }
  %(gpu)s
  return { times, gpu, canvas: e.canvas(), drawCalls: e.stats().drawCalls }; })()'''

# Each timed frame's GPU time from EXT_disjoint_timer_query_webgl2: from its first command to its
# last on the GPU's clock, waits for the CPU's commands included. Results arrive only after the
# page's task ends, hence the wait; null where the extension is missing or the GPU was disjoint.
TIMER = "const gl = document.querySelector('canvas').getContext('webgl2'); const ext = gl.getExtension('EXT_disjoint_timer_query_webgl2'); const queries = [];"
GPU_READ = '''await new Promise((r) => setTimeout(r, 300));
  const disjoint = ext ? gl.getParameter(ext.GPU_DISJOINT_EXT) : true;
  const gpu = ext && !disjoint ? queries.map((q) => gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE) ? gl.getQueryParameter(q, gl.QUERY_RESULT) / 1e6 : null) : null;'''

# The measure's floor: a frame that only clears a canvas of the same size and waits as the others do.
FLOOR_FRAMES = '''(() => { const c = document.createElement('canvas'); c.width = %(w)d; c.height = %(h)d; document.body.append(c);
  const gl = c.getContext('webgl2'); const px = new Uint8Array(4); const frame = () => { gl.clearColor(Math.random(), 0.5, 0.5, 1);
  gl.clear(gl.COLOR_BUFFER_BIT); gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px); };
  for (let i = 0; i < %(warmup)d; i++) frame();
  const times = []; for (let i = 0; i < %(frames)d; i++) { const s = performance.now(); frame(); times.push(performance.now() - s); }
  c.remove(); return { times, gpu: null, canvas: [%(w)d, %(h)d], drawCalls: 0 }; })()'''

# (label, site, query, seconds stepped a frame; 0 = paused clock)
ROWS = [
    ('default view', 'now', 't=10', 0),
    ('three.js ocean example', 'three', '', 0),
    ('three.js ocean example, no bloom', 'three', 'bloom=0', 0),
    ('FFT view', 'now', 't=10&waves=fft', 1 / 60),
    ('FFT view, base build', 'base', 't=10&waves=fft', 1 / 60),
    ('gale', 'now', 't=10&preset=gale', 1 / 60),
    ('floor: clear and wait', 'three', '', 0),
    ('default view, base build', 'base', 't=10', 0),
    ('compare-models camera, gerstner alone', 'now', 't=10&preset=compare-models&compare=off&waves=gerstner', 1 / 60),
    ('compare-models camera, seed alone', 'now', 't=10&preset=compare-models&compare=off&waves=seed', 1 / 60),
    ('interactive waves (a stone)', 'now', 't=10&preset=stone', 1 / 60),
    ('beach view', 'now', 't=10&preset=beach', 1 / 60),
]
if os.environ.get('ONLY'):
    ROWS = [row for row in ROWS if row[0] in os.environ['ONLY'].split(';')]
SHOTS = {'default view': 'default.png', 'FFT view': 'fft.png', 'gale': 'gale.png', 'three.js ocean example': 'three.png'}


def icd_files():
    found = []
    for pattern in ['/usr/local/nvidia/share/vulkan/icd.d/*.json', '/usr/share/vulkan/icd.d/nvidia*.json', '/etc/vulkan/icd.d/nvidia*.json']:
        found += glob.glob(pattern)
    return found


COMMON = ['--no-sandbox', '--no-zygote', '--headless=shell', '--disable-background-networking', '--disable-component-update',
          '--disable-sync', '--no-first-run', '--disable-gpu-vsync', '--hide-scrollbars', '--force-color-profile=srgb',
          f'--window-size={W},{H}', '--ignore-gpu-blocklist', '--enable-gpu-rasterization', '--disable-dev-shm-usage',
          '--user-data-dir=/tmp/oceano-chrome-profile']
# ANGLE on Vulkan; its headless display asks the instance for VK_EXT_headless_surface, which
# NVIDIA's driver lacks: run.sh installs an implicit layer that advertises it (headlessSurfaceLayer.c).
CONFIGS = [('angle-vulkan', ['--use-gl=angle', '--use-angle=vulkan', '--enable-features=Vulkan', '--disable-vulkan-surface'])]
if os.environ.get('DRY_RUN_SOFTWARE'):
    CONFIGS = [('swiftshader', ['--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'])]


def launch(flags, port, name=''):
    env = dict(os.environ)
    # NVIDIA's Vulkan driver needs libglvnd's libGLdispatch, which that image lacks: run.sh unpacks it in /tmp/glroot.
    nvidia_libs = [p for p in ['/usr/local/nvidia/lib64', '/usr/local/nvidia/lib', '/tmp/glroot/usr/lib/x86_64-linux-gnu'] if os.path.isdir(p)]
    env['LD_LIBRARY_PATH'] = ':'.join([f'{CHROME_DIR}/lib', CHROME_DIR] + nvidia_libs)
    icds = icd_files()
    if icds:
        env['VK_DRIVER_FILES'] = env['VK_ICD_FILENAMES'] = icds[0]
    env['FONTCONFIG_PATH'] = CHROME_DIR
    subprocess.run(['rm', '-rf', '/tmp/oceano-chrome-profile'])
    log = open(f'/tmp/chrome-{port}.log', 'w')
    proc = subprocess.Popen([f'{CHROME_DIR}/chromium', *COMMON, *flags, f'--remote-debugging-port={port}', 'about:blank'],
                            env=env, stdout=log, stderr=subprocess.STDOUT)
    deadline = time.time() + 60
    while time.time() < deadline:
        try:
            targets = json.load(urllib.request.urlopen(f'http://127.0.0.1:{port}/json/list', timeout=2))
            pages = [t for t in targets if t.get('type') == 'page']
            if pages:
                return proc, Page(pages[0]['webSocketDebuggerUrl'])
        except Exception:
            pass
        if proc.poll() is not None:
            break
        time.sleep(0.3)
    proc.kill()
    raise RuntimeError(f'Chromium did not open its DevTools port; log tail:\n{open(f"/tmp/chrome-{port}.log").read()[-1500:]}')


def software(renderer):
    return any(s in renderer.lower() for s in ['swiftshader', 'llvmpipe', 'softpipe', 'software', 'no webgl2'])


def main():
    os.makedirs(OUT, exist_ok=True)
    # The build's fonts.conf looks in /tmp/fonts; without a font Skia aborts on the first text it lays out.
    os.makedirs('/tmp/fonts', exist_ok=True)
    subprocess.run(f'cp -r {CHROME_DIR}/fonts/* /tmp/fonts/', shell=True)
    print('Vulkan drivers:', icd_files(), flush=True)
    bases = {name: serve(os.path.join(SITE_DIR, name)) for name in ['now', 'base', 'three']}
    chosen = None
    for i, (name, flags) in enumerate(CONFIGS):
        try:
            proc, page = launch(flags, 9300 + i, name)
            renderer = page.evaluate(RENDERER)
            print(f'{name}: {renderer}', flush=True)
            if not software(renderer) or os.environ.get('DRY_RUN_SOFTWARE'):
                chosen = (name, proc, page, renderer)
                break
            proc.kill()
        except Exception as error:
            print(f'{name}: failed: {error}', flush=True)
            try:
                print(open(f'/tmp/chrome-{9300 + i}.log').read()[-2000:], flush=True)
            except Exception:
                pass
    if chosen is None:
        print('No GPU renderer found.')
        sys.exit(2)
    name, proc, page, renderer = chosen
    results = {'config': name, 'renderer': renderer, 'size': [W, H], 'frames': FRAMES, 'rounds': ROUNDS, 'rows': {}}
    for r in range(ROUNDS):
        order = ROWS[r % len(ROWS):] + ROWS[:r % len(ROWS)]
        for label, site, query, step in order:
            url = bases[site] + (f'?{query}' if query else '')
            page.errors.clear()
            if label.startswith('floor'):
                page.goto(url, 'window.threejsOcean !== undefined')
                measured = page.evaluate(FLOOR_FRAMES % {'warmup': WARMUP, 'frames': FRAMES, 'w': W, 'h': H})
            elif site == 'three':
                page.goto(url, 'window.threejsOcean !== undefined')
                measured = page.evaluate(EXAMPLE_FRAMES % {'warmup': WARMUP, 'frames': FRAMES, 'timer': TIMER, 'gpu': GPU_READ})
            else:
                page.goto(url, 'window.oceano !== undefined')
                t0 = dict(p.split('=') for p in query.split('&')).get('t', '0')
                measured = page.evaluate(OCEAN_FRAMES % {'warmup': WARMUP, 'frames': FRAMES, 't0': t0, 'step': step, 'timer': TIMER, 'gpu': GPU_READ})
            row = results['rows'].setdefault(label, {'site': site, 'query': query, 'medians': [], 'p95s': [], 'errors': []})
            times = sorted(measured['times'])
            row['medians'].append(statistics.median(times))
            gpu = [g for g in (measured.get('gpu') or []) if g is not None]
            row.setdefault('gpuMedians', []).append(statistics.median(gpu) if gpu else None)
            row['p95s'].append(times[int(0.95 * (len(times) - 1))])
            row['canvas'], row['drawCalls'] = measured['canvas'], measured['drawCalls']
            row.setdefault('cpuMs', []).append(measured.get('cpuMs'))
            row['errors'] += page.errors[:3]
            if r == ROUNDS - 1 and label in SHOTS and os.environ.get('SHOTS', '1'):
                page.screenshot(os.path.join(OUT, SHOTS[label]))
            print(f'round {r} {label}: median {row["medians"][-1]:.2f} ms', flush=True)
    proc.kill()
    with open(os.path.join(OUT, 'gpu-frames.json'), 'w') as f:
        json.dump(results, f, indent=1)
    print(f'\nRenderer: {renderer} ({name}), {W}x{H}, {FRAMES} frames a round, {ROUNDS} rounds')
    print(f'{"row":45s} {"median ms":>10s} {"rounds":>24s} {"p95":>7s} {"GPU ms":>7s} canvas  errors')
    for label, row in results['rows'].items():
        m = statistics.median(row['medians'])
        g = [x for x in row['gpuMedians'] if x is not None]
        gpu = f'{statistics.median(g):7.3f}' if g else '    n/a'
        print(f'{label:45s} {m:10.2f} {min(row["medians"]):10.2f}-{max(row["medians"]):<10.2f} {statistics.median(row["p95s"]):7.2f} {gpu} '
              f'{row["canvas"]} {len(row["errors"])} {row["errors"][:1]} cpuMs {row["cpuMs"][-1]}')

    def ratio(a, b):
        if a not in results['rows'] or b not in results['rows']:
            return 'not measured'
        out = []
        for key in ['medians', 'gpuMedians']:
            ra = [x / y for x, y in zip(results['rows'][a][key], results['rows'][b][key]) if x and y]
            out.append(f'{key}: {statistics.median(ra):.2f} (rounds {min(ra):.2f}-{max(ra):.2f})' if ra else f'{key}: n/a')
        return '; '.join(out)
    print('default / three.js example:', ratio('default view', 'three.js ocean example'))
    print('default / three.js example without its bloom (the bench\'s target):', ratio('default view', 'three.js ocean example, no bloom'))
    print('FFT view / FFT view at the base build:', ratio('FFT view', 'FFT view, base build'))
    print('default / default at the base build:', ratio('default view', 'default view, base build'))
    print('interactive waves / default:', ratio('interactive waves (a stone)', 'default view'))
    print('beach view / default:', ratio('beach view', 'default view'))
    print('gerstner / seed (compare-models camera):', ratio('compare-models camera, gerstner alone', 'compare-models camera, seed alone'))


main()
