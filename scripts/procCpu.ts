/**
 * CPU time of Chromium's processes, read from /proc (for the frame probes: SwiftShader draws
 * on the CPU, in the GPU process, so its CPU time is a frame's cost whatever else the machine runs).
 */
import { readdirSync, readFileSync } from 'node:fs';

const TICK_MS = 10; // USER_HZ = 100 on Linux

/** CPU ms (user + system) of every process below `root`, by kind: gpu, renderer, other. */
export function cpuByKind(root: number): Record<string, number> {
  const parents = new Map<number, number>();
  const ticks = new Map<number, number>();
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    try {
      const stat = readFileSync(`/proc/${entry}/stat`, 'utf8');
      const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
      parents.set(Number(entry), Number(fields[1]));
      ticks.set(Number(entry), Number(fields[11]) + Number(fields[12]));
    } catch {
      // the process ended meanwhile
    }
  }
  const below = (pid: number): boolean => pid === root || (parents.has(pid) && pid !== 1 && below(parents.get(pid) as number));
  const out: Record<string, number> = { gpu: 0, renderer: 0, other: 0 };
  for (const [pid, t] of ticks) {
    if (!below(pid)) continue;
    let cmd = '';
    try {
      cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
    } catch {
      continue;
    }
    const kind = cmd.includes('--type=gpu-process') ? 'gpu' : cmd.includes('--type=renderer') ? 'renderer' : 'other';
    out[kind] += t * TICK_MS;
  }
  return out;
}
