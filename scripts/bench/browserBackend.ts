import { BROWSER_ARGS } from '../../tests/browser/harness';

/**
 * Which rasterizer the benchmark's Chromium uses. The browser tests always use SwiftShader
 * so their pictures match everywhere; the benchmark wants the machine's real GPU when it
 * has one, and says which one it got (the WebGL renderer string is in every result).
 */
export type Backend = 'gpu' | 'swiftshader';

/** BENCH_GPU=1 insists on the GPU, BENCH_GPU=0 on SwiftShader; unset tries the GPU first. */
export function requestedBackend(env: string | undefined): Backend | 'auto' {
  if (env === undefined || env === '' || env === 'auto') return 'auto';
  if (env === '1') return 'gpu';
  if (env === '0') return 'swiftshader';
  throw new Error(`BENCH_GPU must be 1 (GPU), 0 (SwiftShader) or unset (GPU if there is one), got "${env}".`);
}

const SWIFTSHADER_FLAGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'];

/** ANGLE on Vulkan is what headless Chromium on Linux needs to reach a discrete GPU. */
const GPU_FLAGS = ['--use-angle=vulkan', '--enable-features=Vulkan', '--disable-vulkan-surface', '--ignore-gpu-blocklist'];

export function backendArgs(backend: Backend): string[] {
  const common = BROWSER_ARGS.filter((flag) => !SWIFTSHADER_FLAGS.includes(flag));
  return [...common, ...(backend === 'gpu' ? GPU_FLAGS : SWIFTSHADER_FLAGS)];
}

/** Software rasterizers a GPU request can silently fall back to. */
export function isSoftwareRenderer(renderer: string): boolean {
  return /swiftshader|llvmpipe|softpipe|software/i.test(renderer);
}
