import { integerNoise, seededRandom } from './integerHash';

/**
 * A seeded stream of standard normal numbers: Box–Muller (Box & Muller 1958, Ann. Math.
 * Statist. 29(2)) on the mulberry32 uniform stream. `stream` separates independent streams
 * (one per cascade) drawn from the same user seed.
 */
export function gaussianRandom(seed: number, stream: number): () => number {
  const uniform = seededRandom(Math.floor((integerNoise(stream, 0x5eed, seed) + 1) * 2147483648));
  let spare: number | null = null;
  return () => {
    if (spare !== null) {
      const s = spare;
      spare = null;
      return s;
    }
    const u1 = 1 - uniform(); // (0, 1]: log never sees 0
    const u2 = uniform();
    const r = Math.sqrt(-2 * Math.log(u1));
    spare = r * Math.sin(2 * Math.PI * u2);
    return r * Math.cos(2 * Math.PI * u2);
  };
}
