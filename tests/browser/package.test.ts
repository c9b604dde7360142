import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import puppeteer, { type Browser } from 'puppeteer';
import { execFile } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { PNG } from 'pngjs';
import ts from 'typescript';
import { serveFolder } from './staticServer';

/**
 * The npm package as a stranger gets it: `npm pack`, the tarball installed with three.js
 * into an empty folder, examples/threejs-scene.html served from there by a plain file server
 * (no bundler, only the page's import map) and looked at in headless Chromium; a user's
 * TypeScript compiled against the installed types; and the built library's imports read.
 */

const ROOT = join(import.meta.dirname, '..', '..');
const EXAMPLE = join(ROOT, 'examples', 'threejs-scene.html');
const BUOYS = join(ROOT, 'examples', 'buoys.html');
const COMPOSER = join(ROOT, 'examples', 'composer.html');
const SPLIT = join(ROOT, 'examples', 'split-screen.html');
const SPLIT_SHOT = process.env.SPLIT_SHOT ?? '';
const COMPOSER_SHOT = process.env.COMPOSER_SHOT ?? '';
const SHOTS = process.env.BUOYS_SHOT ?? '';
const CONSUMER = join(ROOT, 'tests', 'browser', 'fixtures', 'package-consumer');
const TSC = join(ROOT, 'node_modules', 'typescript', 'bin', 'tsc');
const NPM = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const exec = promisify(execFile);

/** What `npm run build:package` writes, and what it is built from. */
const PACKAGE_OUTPUTS = ['dist/lib/oceano.js', 'dist/lib/types/index.d.ts', 'dist/element/oceano-view.js'];
const PACKAGE_INPUTS = [
  'src',
  'shaders',
  'public',
  'scripts',
  'package.json',
  'package-lock.json',
  'vite.config.ts',
  'vite.lib.config.ts',
  'tsconfig.json',
  'tsconfig.lib.json',
];

function newestChange(path: string): number {
  const stat = statSync(path);
  if (!stat.isDirectory()) return stat.mtimeMs;
  return Math.max(stat.mtimeMs, ...readdirSync(path).map((entry) => newestChange(join(path, entry))));
}

/** A package build newer than every file it is made from (rerunning this test alone) is packed as it is. */
function packageBuildIsFresh(): boolean {
  const outputs = PACKAGE_OUTPUTS.map((file) => join(ROOT, file));
  if (!outputs.every((file) => existsSync(file))) return false;
  const built = Math.min(...outputs.map((file) => statSync(file).mtimeMs));
  return PACKAGE_INPUTS.map((input) => join(ROOT, input)).every((input) => !existsSync(input) || newestChange(input) < built);
}

/**
 * The environment for the npm commands this test runs: without the variables a surrounding
 * `npm test` sets (its package, its prefix), which would point them back at the repository.
 * The registry, cache and proxy settings stay.
 */
function npmEnvironment(): NodeJS.ProcessEnv {
  const kept = /^npm_config_(registry|cache|userconfig|globalconfig|https?_proxy|proxy|noproxy|cafile|strict_ssl)$/i;
  return Object.fromEntries(Object.entries(process.env).filter(([name]) => !/^npm_/i.test(name) || kept.test(name)));
}

async function npm(args: string[], cwd: string): Promise<void> {
  await exec(NPM, args, { cwd, env: npmEnvironment(), maxBuffer: 64 * 1024 * 1024, shell: process.platform === 'win32' });
}

function installedVersion(name: string): string {
  return (JSON.parse(readFileSync(join(ROOT, 'node_modules', name, 'package.json'), 'utf8')) as { version: string }).version;
}

/** Module specifiers that name a package rather than a file or URL: `three`, `fft.js`, `three/addons/…`. */
function bareImports(code: string): string[] {
  return ts
    .preProcessFile(code, true, true)
    .importedFiles.map((file) => file.fileName)
    .filter((name) => !/^(\.{1,2}\/|\/|[a-z][a-z0-9+.-]*:)/i.test(name));
}

const isThreeImport = (name: string): boolean => name === 'three' || name.startsWith('three/addons/');

function filesUnder(folder: string): string[] {
  return readdirSync(folder, { recursive: true, encoding: 'utf8' }).filter((file) => statSync(join(folder, file)).isFile());
}

interface Colour {
  r: number;
  g: number;
  b: number;
}

/** The mean colour of rows [fromRow, toRow), and their detail: the mean difference between side-by-side pixels, levels a channel. */
function rowsSeen(png: PNG, fromRow: number, toRow: number): { colour: Colour; detail: number } {
  const sum = { r: 0, g: 0, b: 0 };
  let differences = 0;
  for (let y = fromRow; y < toRow; y++) {
    for (let x = 0; x < png.width; x++) {
      const i = (y * png.width + x) * 4;
      sum.r += png.data[i];
      sum.g += png.data[i + 1];
      sum.b += png.data[i + 2];
      if (x > 0) for (let c = 0; c < 3; c++) differences += Math.abs(png.data[i + c] - png.data[i + c - 4]);
    }
  }
  const n = (toRow - fromRow) * png.width;
  return { colour: { r: sum.r / n, g: sum.g / n, b: sum.b / n }, detail: differences / ((toRow - fromRow) * (png.width - 1) * 3) };
}

const distance = (a: Colour, b: Colour): number => Math.hypot(a.r - b.r, a.g - b.g, a.b - b.b);
const brightness = (c: Colour): number => (c.r + c.g + c.b) / 3;

/**
 * What is wrong with a picture that should show sky above and sea below; empty when nothing
 * is. The painted sky below the horizon is sea-coloured too, so the sea is told from it by
 * its waves: detail that a smooth sky has not (example at 480×270: 1.9 levels against 0.0).
 */
function seaAndSkyFaults(png: PNG, seaBand = 0.15, minDetail = 0.75): string[] {
  const band = Math.round(png.height * 0.15);
  const sky = rowsSeen(png, 0, band).colour;
  const sea = rowsSeen(png, png.height - Math.round(png.height * seaBand), png.height);
  const whole = rowsSeen(png, 0, png.height).colour;
  let spread = 0;
  for (let i = 0; i < png.data.length; i += 4)
    spread = Math.max(spread, distance({ r: png.data[i], g: png.data[i + 1], b: png.data[i + 2] }, whole));
  const named = (c: Colour): string => `rgb(${c.r.toFixed(0)}, ${c.g.toFixed(0)}, ${c.b.toFixed(0)})`;
  const faults: string[] = [];
  if (spread < 20) faults.push(`blank: every pixel within ${spread.toFixed(1)} levels of ${named(whole)}`);
  if (!(sky.b > sky.r && brightness(sky) > 100)) faults.push(`the top rows are not sky: ${named(sky)}`);
  if (!(sea.colour.b > sea.colour.r && brightness(sea.colour) < brightness(sky)))
    faults.push(`the bottom rows are not water below a brighter sky: ${named(sea.colour)}`);
  if (distance(sky, sea.colour) < 40) faults.push(`sky ${named(sky)} and sea ${named(sea.colour)} are alike`);
  if (sea.detail < minDetail) faults.push(`no waves: the bottom rows' detail is ${sea.detail.toFixed(2)} levels`);
  return faults;
}

/**
 * The sea reaches the horizon at row fraction `horizon`: the rows just below it are darker than
 * the sky just above by at least 32 luminance levels (sea to the horizon: 41 with the sun's glitter
 * there, 86 without; a view whose far chunks were culled for another camera, its haze band showing
 * through: 15 to 24).
 */
function horizonFaults(png: PNG, horizon: number): string[] {
  const rows = (from: number, to: number) => rowsSeen(png, Math.round(from * png.height), Math.round(to * png.height)).colour;
  const luma = (c: Colour) => 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  const step = luma(rows(horizon - 0.06, horizon - 0.02)) - luma(rows(horizon + 0.02, horizon + 0.06));
  return step < 32 ? [`no sea up to the horizon: the rows below it are only ${step.toFixed(0)} levels darker than the sky above`] : [];
}

/** What a user of `Ocean` may call, beside what three.js's Object3D gives it. */
const OCEAN_PUBLIC_MEMBERS = [
  'autoUpdate',
  'constructor',
  'dispose',
  'disturb',
  'getParams',
  'sampleSurface',
  'sampleSurfaces',
  'setParams',
  'setSky',
  'sky',
  'submersion',
  'time',
  'update',
  'whenReady',
].sort();

/** The names `import { … } from 'oceano'` offers, values and types. */
const PACKAGE_EXPORTS = [
  'defaultOceanOptions',
  'EncodedScene',
  'LiveWaveModel',
  'Ocean',
  'oceanOptionDefs',
  'OceanOptions',
  'OceanParameters',
  'OceanParamKey',
  'OceanUnderwater',
  'OceanUnderwaterOptions',
  'OceanUnderwaterPass',
  'OceanUnderwaterPassOptions',
  'SampleSurfacesOptions',
  'Submersion',
  'SurfacePoints',
  'SurfaceSample',
  'SurfaceSamples',
  'validateOceanOptions',
  'WavesChoice',
].sort();

/** The names the package's index.d.ts (under `types`) exports, read by the TypeScript checker. */
function moduleExports(types: string): string[] {
  const index = join(types, 'index.d.ts');
  const program = ts.createProgram([index], { types: [], skipLibCheck: true, noEmit: true });
  const checker = program.getTypeChecker();
  return checker
    .getExportsOfModule(checker.getSymbolAtLocation(program.getSourceFile(index)!)!)
    .map((entry) => entry.name)
    .sort();
}

/**
 * The public members a user of `className` (exported from the package's index.d.ts under
 * `types`) sees, its base classes' included and Object3D's left out: read by the TypeScript
 * checker, as the user's editor reads them.
 */
function publicMembers(types: string, className: string): string[] {
  const index = join(types, 'index.d.ts');
  const program = ts.createProgram([index], { types: [], skipLibCheck: true, noEmit: true });
  const checker = program.getTypeChecker();
  const exported = checker.getExportsOfModule(checker.getSymbolAtLocation(program.getSourceFile(index)!)!);
  const symbol = exported.find((entry) => entry.name === className)!;
  const instance = checker.getDeclaredTypeOfSymbol(checker.getAliasedSymbol(symbol));
  const own = checker.getPropertiesOfType(instance).filter((property) => {
    const declaration = property.valueDeclaration ?? property.declarations?.[0];
    const inPackage =
      declaration !== undefined &&
      !declaration.getSourceFile().fileName.includes('/node_modules/three/') &&
      !declaration.getSourceFile().fileName.includes('/@types/three/');
    const hidden =
      declaration !== undefined &&
      (ts.getCombinedModifierFlags(declaration) & (ts.ModifierFlags.Private | ts.ModifierFlags.Protected)) !== 0;
    return inPackage && !hidden;
  });
  return ['constructor', ...own.map((property) => property.name)].sort();
}

describe('the npm package', () => {
  let work = '';
  let site = '';
  let browser: Browser;

  beforeAll(async () => {
    work = mkdtempSync(join(tmpdir(), 'oceano-package-'));
    const tarballs = join(work, 'tarball');
    site = join(work, 'site');
    mkdirSync(tarballs);
    mkdirSync(site);
    // prepack builds the library, the element and the types unless they are already newer than their sources.
    await npm(['pack', '--pack-destination', tarballs, ...(packageBuildIsFresh() ? ['--ignore-scripts'] : [])], ROOT);
    const [tarball] = readdirSync(tarballs).filter((file) => file.endsWith('.tgz'));
    writeFileSync(join(site, 'package.json'), JSON.stringify({ name: 'oceano-package-user', private: true, type: 'module' }));
    await npm(
      [
        'install',
        '--prefer-offline',
        '--no-audit',
        '--no-fund',
        join(tarballs, tarball),
        `three@${installedVersion('three')}`,
        `@types/three@${installedVersion('@types/three')}`,
      ],
      site,
    );
    browser = await puppeteer.connect({ browserWSEndpoint: inject('browserEndpoint') });
  }, 600_000);

  afterAll(async () => {
    await browser?.disconnect();
    if (work) rmSync(work, { recursive: true, force: true });
  });

  it("holds the library, its types, the element and the element's boat, and nothing else", () => {
    const installed = join(site, 'node_modules', 'oceano');
    expect(readdirSync(installed).sort()).toEqual(['LICENSE', 'README.md', 'dist', 'package.json']);
    const files = filesUnder(join(installed, 'dist'));
    for (const file of [
      'lib/oceano.js',
      'lib/types/index.d.ts',
      'lib/types/element.d.ts',
      'element/oceano-view.js',
      'element/models/boat.glb',
    ])
      expect(files).toContain(file);
    // The FFT twin's Worker ships beside the library that starts it.
    expect(files.filter((file) => /^lib\/assets\/fftFieldsWorker-[\w-]+\.js$/.test(file))).toHaveLength(1);
  });

  it("leaves three and its addons as the library's only bare imports; everything else is bundled", () => {
    const lib = join(site, 'node_modules', 'oceano', 'dist', 'lib');
    const scripts = filesUnder(lib).filter((file) => file.endsWith('.js'));
    const imports = new Set(scripts.flatMap((file) => bareImports(readFileSync(join(lib, file), 'utf8'))));
    expect(imports).toContain('three');
    expect([...imports].filter((name) => !isThreeImport(name))).toEqual([]);
    // Control: a dependency left unbundled, in each form an import can take, is seen.
    const planted =
      'import FFT from "fft.js";\nexport { GUI } from "lil-gui";\nconst plot = () => import("uplot");\nimport { Water } from "three/examples/jsm/objects/Water.js";';
    expect(bareImports(planted).filter((name) => !isThreeImport(name))).toEqual([
      'fft.js',
      'lil-gui',
      'uplot',
      'three/examples/jsm/objects/Water.js',
    ]);
  });

  it("compiles a three.js user's TypeScript against the installed types", async () => {
    const project = join(site, 'consumer');
    cpSync(CONSUMER, project, { recursive: true });
    const compile = (...options: string[]) =>
      exec(process.execPath, [TSC, '-p', join(project, 'tsconfig.json'), ...options], { cwd: project });
    // Our declaration files are checked too (no skipLibCheck): one that names a module the package lacks fails here.
    await expect(compile()).resolves.toBeDefined();
    // Control: without its @ts-expect-error each wrongly typed line fails the compile (a wrong
    // value TS2322, a key Ocean does not read TS2353; the declarations, just checked, are
    // skipped this time: only the user's file matters).
    const source = readFileSync(join(project, 'consumer.ts'), 'utf8');
    const marks = source.match(/^\s*\/\/ @ts-expect-error.*\n/gm) ?? [];
    expect(marks).toHaveLength(6);
    writeFileSync(join(project, 'consumer.ts'), source.replace(/^\s*\/\/ @ts-expect-error.*\n/gm, ''));
    const failed = await compile('--skipLibCheck').then(
      () => '',
      (error: { stdout: string }) => error.stdout,
    );
    expect(failed.match(/consumer\.ts\(\d+,\d+\): error TS\d+/g)?.map((line) => line.replace(/^.*error /, ''))).toEqual([
      'TS2322',
      'TS2353',
      'TS2353',
      'TS2353',
      'TS2339',
      'TS2353',
    ]);
  });

  it("exports what a library user needs, the options an Ocean reads among them, and none of the app's parameters", () => {
    const types = join(site, 'node_modules', 'oceano', 'dist', 'lib', 'types');
    expect(moduleExports(types)).toEqual(PACKAGE_EXPORTS);
    // Control: an export planted in the installed declarations is seen.
    const index = join(types, 'index.d.ts');
    const declared = readFileSync(index, 'utf8');
    writeFileSync(index, `${declared}\nexport { defaultParams } from './sim/params/params';\n`);
    try {
      expect(moduleExports(types)).toEqual([...PACKAGE_EXPORTS, 'defaultParams'].sort());
    } finally {
      writeFileSync(index, declared);
    }
  });

  it("publishes exactly Ocean's intended members: the app's plumbing and the test hooks are not in its types", () => {
    const types = join(site, 'node_modules', 'oceano', 'dist', 'lib', 'types');
    expect(publicMembers(types, 'Ocean')).toEqual(OCEAN_PUBLIC_MEMBERS);
    expect(publicMembers(types, 'OceanUnderwater')).not.toContain('forceShaftLightWindow');
    // Control: a public member planted in the installed declarations is seen.
    const engine = join(types, 'render', 'ocean', 'oceanEngine.d.ts');
    const declared = readFileSync(engine, 'utf8');
    writeFileSync(engine, declared.replace('    dispose(): void;', '    dispose(): void;\n    readonly binding: unknown;'));
    try {
      expect(publicMembers(types, 'Ocean')).toEqual([...OCEAN_PUBLIC_MEMBERS, 'binding'].sort());
    } finally {
      writeFileSync(engine, declared);
    }
  });

  describe('examples/threejs-scene.html, served as files', () => {
    const example = readFileSync(EXAMPLE, 'utf8');
    /** The example with `lines` taken out; each must be there to take. */
    const without = (...lines: string[]): string =>
      lines.reduce((page, line) => {
        expect(page).toContain(line);
        return page.replace(line, '');
      }, example);

    let pagesWritten = 0;
    async function look(page: string): Promise<{ faults: string[]; errors: string[]; missing: string[]; workers: string[] }> {
      const name = `page-${++pagesWritten}.html`;
      writeFileSync(join(site, name), page);
      const missing: string[] = [];
      const { server, url } = await serveFolder(site, '/courses/graphics/week-3/', (path, status) => {
        if (status !== 200) missing.push(path);
      });
      const tab = await browser.newPage();
      try {
        tab.setDefaultTimeout(120_000);
        const errors: string[] = [];
        tab.on('pageerror', (error) => errors.push(String(error)));
        tab.on('console', (message) => {
          if (message.type() === 'error' && !message.location().url?.endsWith('/favicon.ico')) errors.push(message.text());
        });
        // Counts the animation loop's frames, so that every page is looked at after the same number.
        await tab.evaluateOnNewDocument(() => {
          const request = window.requestAnimationFrame.bind(window);
          const counted = window as unknown as { framesStarted: number };
          counted.framesStarted = 0;
          window.requestAnimationFrame = (callback) =>
            request((time) => {
              counted.framesStarted++;
              callback(time);
            });
        });
        await tab.setViewport({ width: 480, height: 270, deviceScaleFactor: 1 });
        await tab.goto(`${url}${name}`, { waitUntil: 'load' });
        await tab.waitForFunction(() => (window as unknown as { framesStarted: number }).framesStarted >= 12);
        const png = PNG.sync.read(Buffer.from(await tab.screenshot({ type: 'png' })));
        return {
          faults: seaAndSkyFaults(png),
          errors,
          missing: missing.filter((path) => !path.endsWith('/favicon.ico')),
          workers: tab.workers().map((worker) => worker.url()),
        };
      } finally {
        await tab.close();
        server.close();
      }
    }

    it("shows sea below sky, with no error and the FFT twin's Worker running from the installed package", async () => {
      const seen = await look(example);
      expect(seen.errors).toEqual([]);
      expect(seen.missing).toEqual([]);
      expect(seen.faults).toEqual([]);
      expect(seen.workers).toEqual([expect.stringMatching(/\/node_modules\/oceano\/dist\/lib\/assets\/fftFieldsWorker-[\w-]+\.js$/)]);
    });

    it('control: without the Ocean in the scene the picture is blank', async () => {
      const seen = await look(without('scene.add(ocean);', 'scene.add(ocean.sky);'));
      expect(seen.faults).toContainEqual(expect.stringMatching(/^blank/));
    });

    it('control: the sky alone, its sea-coloured lower half without waves, is not taken for sea and sky', async () => {
      const seen = await look(without('scene.add(ocean);'));
      expect(seen.faults).toEqual([expect.stringMatching(/^no waves/)]);
    });
  });

  describe('examples/buoys.html, served as files', () => {
    const page = readFileSync(BUOYS, 'utf8');
    const FOLLOW = 'buoy.position.y = samples[4 * i];';

    /** The page's buoys after 12 frames: how many float off their own sample of the sea, how many sit low, and the picture's faults. */
    async function float(html: string): Promise<{ errors: string[]; faults: string[]; count: number; offSample: number; spread: number }> {
      writeFileSync(join(site, 'buoys.html'), html);
      const { server, url } = await serveFolder(site, '/courses/graphics/week-3/');
      const tab = await browser.newPage();
      try {
        tab.setDefaultTimeout(120_000);
        const errors: string[] = [];
        tab.on('pageerror', (error) => errors.push(String(error)));
        await tab.setViewport({ width: 480, height: 270, deviceScaleFactor: 1 });
        await tab.goto(`${url}buoys.html`, { waitUntil: 'load' });
        await tab.waitForFunction(() => (window as unknown as { buoys?: unknown }).buoys);
        await tab.waitForFunction(() => (window as unknown as { buoys: { ocean: { time: number } } }).buoys.ocean.time > 0.5);
        const png = PNG.sync.read(Buffer.from(await tab.screenshot({ type: 'png' })));
        if (SHOTS && html === page) writeFileSync(SHOTS, PNG.sync.write(png));
        // In a frame, after the page's own loop: each buoy's y against that frame's sample under it (the frame's
        // own fields; no Worker reply can land between two callbacks of one frame), as the Float32Array stores it.
        const seen = await tab.evaluate(
          () =>
            new Promise<{ count: number; offSample: number; spread: number }>((resolve) =>
              requestAnimationFrame(() => {
                const { ocean, buoys } = (
                  window as unknown as {
                    buoys: {
                      ocean: { sampleSurfaces(points: Float32Array): Float32Array };
                      buoys: { position: { x: number; y: number; z: number } }[];
                    };
                  }
                ).buoys;
                const heights = buoys.map((b) => ocean.sampleSurfaces(Float32Array.of(b.position.x, b.position.z))[0]);
                const ys = buoys.map((b) => b.position.y);
                resolve({
                  count: buoys.length,
                  offSample: ys.filter((y, i) => y !== heights[i]).length,
                  spread: Math.max(...ys) - Math.min(...ys),
                });
              }),
            ),
        );
        return { errors, faults: seaAndSkyFaults(png), ...seen };
      } finally {
        await tab.close();
        server.close();
      }
    }

    it('floats 200 buoys, each at the height of its own sample of the FFT sea, under the sky', async () => {
      expect(page.split('\n').length).toBeLessThanOrEqual(80);
      const seen = await float(page);
      expect(seen.errors).toEqual([]);
      expect(seen.faults).toEqual([]);
      expect(seen).toMatchObject({ count: 200, offSample: 0 });
      // They ride the waves: not one plane of buoys.
      expect(seen.spread).toBeGreaterThan(0.2);
    });

    it('control: buoys that do not follow their samples are seen off the sea', async () => {
      expect(page).toContain(FOLLOW);
      const seen = await float(page.replace(FOLLOW, ''));
      expect(seen.offSample).toBeGreaterThan(150);
    });
  });

  describe('examples/composer.html, served as files', () => {
    const page = readFileSync(COMPOSER, 'utf8');
    const PASS = 'composer.addPass(new OceanUnderwaterPass(ocean, camera));';

    /** The page after 12 frames: its errors and the mean colour and detail of its bottom rows, under the water. */
    async function compose(html: string): Promise<{ errors: string[]; water: { colour: Colour; detail: number }; png: PNG }> {
      writeFileSync(join(site, 'composer.html'), html);
      const { server, url } = await serveFolder(site, '/courses/graphics/week-3/');
      const tab = await browser.newPage();
      try {
        tab.setDefaultTimeout(120_000);
        const errors: string[] = [];
        tab.on('pageerror', (error) => errors.push(String(error)));
        tab.on('console', (message) => {
          if (message.type() === 'error' && !message.location().url?.endsWith('/favicon.ico')) errors.push(message.text());
        });
        await tab.evaluateOnNewDocument(() => {
          const request = window.requestAnimationFrame.bind(window);
          const counted = window as unknown as { framesStarted: number };
          counted.framesStarted = 0;
          window.requestAnimationFrame = (callback) => request((time) => (counted.framesStarted++, callback(time)));
        });
        await tab.setViewport({ width: 480, height: 270, deviceScaleFactor: 1 });
        await tab.goto(`${url}composer.html`, { waitUntil: 'load' });
        await tab.waitForFunction(() => (window as unknown as { framesStarted: number }).framesStarted >= 12);
        const png = PNG.sync.read(Buffer.from(await tab.screenshot({ type: 'png' })));
        return { errors, water: rowsSeen(png, Math.round(png.height * 0.7), png.height), png };
      } finally {
        await tab.close();
        server.close();
      }
    }

    it("draws the waterline frame through the user's composer: bloom and the underwater pass, no error", async () => {
      expect(page.split('\n').length).toBeLessThanOrEqual(80);
      const seen = await compose(page);
      if (COMPOSER_SHOT) writeFileSync(COMPOSER_SHOT, PNG.sync.write(seen.png));
      expect(seen.errors).toEqual([]);
      // Under the water, fog: blue-green, and blurred smooth.
      expect(seen.water.colour.b).toBeGreaterThan(seen.water.colour.r);
      const without = await compose(page.replace(PASS, ''));
      expect(without.errors).toEqual([]);
      console.log(`[oceano] composer.html water rows: ${JSON.stringify(seen.water)}; without the pass: ${JSON.stringify(without.water)}`);
      // Control: without the pass the water rows are another picture.
      expect(distance(seen.water.colour, without.water.colour)).toBeGreaterThan(15);
    });
  });

  describe('examples/split-screen.html, served as files', () => {
    const page = readFileSync(SPLIT, 'utf8');
    const AUTO = "{ waves: 'fft', windSpeed: 12, autoUpdate: true }";
    const LOOP = 'renderer.setAnimationLoop(() => {';
    /** The page by hand: autoUpdate off, one update a frame, for the left player's camera only. */
    const handDriven = page
      .replace(AUTO, "{ waves: 'fft', windSpeed: 12 }")
      .replace(LOOP, 'renderer.setAnimationLoop((ms) => { ocean.update(ms / 1000, players[0]);');

    /** The page after 12 frames: its errors and each half's faults as a picture of sea and sky. */
    async function halves(html: string): Promise<{ errors: string[]; left: string[]; right: string[]; png: PNG }> {
      writeFileSync(join(site, 'split-screen.html'), html);
      const { server, url } = await serveFolder(site, '/courses/graphics/week-3/');
      const tab = await browser.newPage();
      try {
        tab.setDefaultTimeout(120_000);
        const errors: string[] = [];
        tab.on('pageerror', (error) => errors.push(String(error)));
        tab.on('console', (message) => {
          if (message.type() === 'error' && !message.location().url?.endsWith('/favicon.ico')) errors.push(message.text());
        });
        await tab.evaluateOnNewDocument(() => {
          const request = window.requestAnimationFrame.bind(window);
          const counted = window as unknown as { framesStarted: number };
          counted.framesStarted = 0;
          window.requestAnimationFrame = (callback) => request((time) => (counted.framesStarted++, callback(time)));
        });
        await tab.setViewport({ width: 640, height: 270, deviceScaleFactor: 1 });
        await tab.goto(`${url}split-screen.html`, { waitUntil: 'load' });
        await tab.waitForFunction(() => (window as unknown as { framesStarted: number }).framesStarted >= 12);
        const png = PNG.sync.read(Buffer.from(await tab.screenshot({ type: 'png' })));
        const half = (x: number): PNG => {
          const part = new PNG({ width: png.width / 2, height: png.height });
          PNG.bitblt(png, part, x, 0, png.width / 2, png.height, 0, 0);
          return part;
        };
        // A half is narrow: one long trough can fill its bottom rows, so the waves are looked for in its
        // lower 40 % with a lower bar (correct halves read 0.62 to 1.9 levels, a painted sky 0.0), and the sea
        // must reach the horizon (at 0.355 of the height for the cameras' 0.15 rad tilt).
        const faults = (part: PNG) => [...seaAndSkyFaults(part, 0.4, 0.4), ...horizonFaults(part, 0.355)];
        return { errors, left: faults(half(0)), right: faults(half(png.width / 2)), png };
      } finally {
        await tab.close();
        server.close();
      }
    }

    it('shows sea below sky in both halves, one camera each, with autoUpdate and no update call', async () => {
      expect(page.split('\n').length).toBeLessThanOrEqual(80);
      expect(page).not.toContain('ocean.update(');
      const seen = await halves(page);
      if (SPLIT_SHOT) writeFileSync(SPLIT_SHOT, PNG.sync.write(seen.png));
      expect(seen.errors).toEqual([]);
      expect(seen.left).toEqual([]);
      expect(seen.right).toEqual([]);
    });

    it('control: updated by hand for the left camera only, the right half misses its sea', async () => {
      expect(page).toContain(AUTO);
      expect(page).toContain(LOOP);
      const seen = await halves(handDriven);
      console.log(`[oceano] split-screen.html by hand for the left camera: right half ${JSON.stringify(seen.right)}`);
      expect(seen.errors).toEqual([]);
      expect(seen.left).toEqual([]);
      expect(seen.right).not.toEqual([]);
    });
  });

  it('registers <oceano-view> from oceano/element, with its boat found beside it', async () => {
    writeFileSync(
      join(site, 'element.html'),
      '<!doctype html><script type="module" src="./node_modules/oceano/dist/element/oceano-view.js"></script><oceano-view t="3" style="display:block;width:320px;height:180px"></oceano-view>',
    );
    const served: string[] = [];
    const missing: string[] = [];
    const { server, url } = await serveFolder(site, '/courses/graphics/week-3/', (path, status) =>
      (status === 200 ? served : missing).push(path),
    );
    const tab = await browser.newPage();
    try {
      tab.setDefaultTimeout(120_000);
      const errors: string[] = [];
      tab.on('pageerror', (error) => errors.push(String(error)));
      await tab.goto(`${url}element.html`, { waitUntil: 'load' });
      await tab.waitForFunction(() => (document.querySelector('oceano-view') as { oceano?: { ready: Promise<unknown> } } | null)?.oceano);
      await tab.evaluate(() => (document.querySelector('oceano-view') as unknown as { oceano: { ready: Promise<unknown> } }).oceano.ready);
      expect(errors).toEqual([]);
      expect(missing.filter((path) => !path.endsWith('/favicon.ico'))).toEqual([]);
      expect(served).toContainEqual(expect.stringMatching(/\/node_modules\/oceano\/dist\/element\/models\/boat\.glb$/));
    } finally {
      await tab.close();
      server.close();
    }
  });

  // The FFT figure's Worker comes from the CDN too.
  it('registers <oceano-view> from a CDN that mirrors npm, with no configuration: a wave and an FFT figure', async () => {
    // The CDN: the installed package under /npm/oceano@VERSION/, on another origin (port), with the CORS header such CDNs send.
    const version = (JSON.parse(readFileSync(join(site, 'node_modules', 'oceano', 'package.json'), 'utf8')) as { version: string }).version;
    const fromCdn: string[] = [];
    const cdn = await serveFolder(
      join(site, 'node_modules', 'oceano'),
      `/npm/oceano@${version}/`,
      (path, status) => fromCdn.push(`${status} ${path}`),
      { 'access-control-allow-origin': '*' },
    );
    const script = `${cdn.url}dist/element/oceano-view.js`;
    const course = join(work, 'course');
    mkdirSync(course, { recursive: true });
    writeFileSync(
      join(course, 'chapter.html'),
      `<!doctype html><script type="module" src="${script}"></script>` +
        '<oceano-view id="seed" t="3" style="display:block;width:320px"></oceano-view><oceano-view id="fft" waves="fft" t="3" style="display:block;width:320px"></oceano-view>',
    );
    const page = await serveFolder(course, '/courses/graphics/week-3/');
    const tab = await browser.newPage();
    try {
      tab.setDefaultTimeout(120_000);
      const errors: string[] = [];
      tab.on('pageerror', (error) => errors.push(String(error)));
      tab.on('console', (message) => {
        if (message.type() === 'error' && !message.location().url?.endsWith('/favicon.ico')) errors.push(message.text());
      });
      await tab.goto(`${page.url}chapter.html`, { waitUntil: 'load' });
      for (const id of ['seed', 'fft']) {
        await tab.waitForFunction((i) => (document.getElementById(i) as { oceano?: unknown } | null)?.oceano, {}, id);
        await tab.evaluate((i) => (document.getElementById(i) as unknown as { oceano: { ready: Promise<unknown> } }).oceano.ready, id);
      }
      const workers = tab.workers().map((worker) => worker.url());
      // Control: the page may not start the CDN's Worker script itself; the element's stand-in does.
      const direct = await tab.evaluate(
        (url) => {
          try {
            new Worker(url, { type: 'module' }).terminate();
            return 'started';
          } catch (error) {
            return (error as Error).name;
          }
        },
        `${cdn.url}${fromCdn
          .map((line) => line.split(' ')[1])
          .find((path) => /fftFieldsWorker-[\w-]+\.js$/.test(path))!
          .slice(`/npm/oceano@${version}/`.length)}`,
      );
      expect(errors).toEqual([]);
      expect(fromCdn.filter((line) => !line.startsWith('200 '))).toEqual([]);
      expect(fromCdn).toContainEqual(expect.stringMatching(/^200 .*\/dist\/element\/models\/boat\.glb$/));
      expect(fromCdn).toContainEqual(expect.stringMatching(/^200 .*\/dist\/element\/assets\/fftFieldsWorker-[\w-]+\.js$/));
      expect(workers).toEqual([expect.stringMatching(/^blob:/)]);
      expect(direct).toBe('SecurityError');
    } finally {
      await tab.close();
      page.server.close();
      cdn.server.close();
    }
  });
});
