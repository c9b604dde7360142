import { readdirSync, readFileSync } from 'node:fs';

const TICK_MS = 10; // USER_HZ = 100 on Linux

export type ProcessKind = 'gpu' | 'renderer' | 'other';

/**
 * CPU ms (user + system) so far of each process below `root` (a browser's pid), with its
 * kind: gpu (where SwiftShader draws), renderer, other. Resolution 10 ms.
 */
export function processCpu(root: number): Map<number, { kind: ProcessKind; ms: number }> {
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
  const out = new Map<number, { kind: ProcessKind; ms: number }>();
  for (const [pid, t] of ticks) {
    if (!below(pid)) continue;
    let cmd = '';
    try {
      cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
    } catch {
      continue;
    }
    const kind = cmd.includes('--type=gpu-process') ? 'gpu' : cmd.includes('--type=renderer') ? 'renderer' : 'other';
    out.set(pid, { kind, ms: t * TICK_MS });
  }
  return out;
}

/**
 * CPU ms by kind of the processes below `root`, counted from `since` (an earlier
 * processCpu reading; processes started after it count from zero). On a machine shared
 * with other jobs wall times swing by 2×; the CPU time a process spent is its cost
 * whatever else runs.
 */
export function cpuByKind(root: number, since?: ReturnType<typeof processCpu>): Record<ProcessKind, number> {
  const out: Record<ProcessKind, number> = { gpu: 0, renderer: 0, other: 0 };
  for (const [pid, { kind, ms }] of processCpu(root)) out[kind] += ms - (since?.get(pid)?.ms ?? 0);
  return out;
}
