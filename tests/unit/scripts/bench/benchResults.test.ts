import { describe, expect, it } from 'vitest';
import { formatFigure, markdownTable } from '../../../../scripts/bench/resultsTable';
import { backendArgs, isSoftwareRenderer, requestedBackend } from '../../../../scripts/bench/browserBackend';

describe('benchmark results table', () => {
  it('renders headings, a separator and one line per row', () => {
    expect(
      markdownTable(
        ['scenario', 'ms'],
        [
          ['default view', '236.0'],
          ['lod', '12.5'],
        ],
      ),
    ).toBe('| scenario | ms |\n| --- | --- |\n| default view | 236.0 |\n| lod | 12.5 |');
  });
  it('escapes pipes and flattens line breaks inside cells', () => {
    expect(markdownTable(['a'], [['x|y\nz']])).toBe('| a |\n| --- |\n| x\\|y z |');
  });
  it('refuses a row whose length does not match the headings', () => {
    expect(() => markdownTable(['a', 'b'], [['only one']])).toThrow(/Row 0 has 1 cells for 2 headings/);
  });
  it('formats figures with fixed decimals and a dash for what was not measured', () => {
    expect(formatFigure(3.14159, 2)).toBe('3.14');
    expect(formatFigure(1500, 0)).toBe('1500');
    expect(formatFigure(null, 1)).toBe('—');
    expect(formatFigure(Number.NaN, 1)).toBe('—');
  });
});

describe('benchmark browser backend', () => {
  it('reads BENCH_GPU: 1 for the GPU, 0 for SwiftShader, unset for auto, anything else refused', () => {
    expect(requestedBackend('1')).toBe('gpu');
    expect(requestedBackend('0')).toBe('swiftshader');
    expect(requestedBackend(undefined)).toBe('auto');
    expect(requestedBackend('')).toBe('auto');
    expect(() => requestedBackend('yes')).toThrow(/BENCH_GPU/);
  });
  it('gives SwiftShader flags only to the SwiftShader backend', () => {
    expect(backendArgs('swiftshader')).toContain('--use-angle=swiftshader');
    expect(backendArgs('gpu')).not.toContain('--use-angle=swiftshader');
    expect(backendArgs('gpu')).not.toContain('--enable-unsafe-swiftshader');
    expect(backendArgs('gpu')).toContain('--use-angle=vulkan');
    expect(backendArgs('gpu')).toContain('--no-sandbox');
  });
  it('tells software renderers from GPUs by their renderer strings', () => {
    expect(isSoftwareRenderer('ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)')).toBe(true);
    expect(isSoftwareRenderer('ANGLE (Mesa, llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5)')).toBe(true);
    expect(isSoftwareRenderer('ANGLE (NVIDIA, Vulkan 1.3.277 (NVIDIA H100 80GB HBM3 (0x00002330)), NVIDIA)')).toBe(false);
  });
});
