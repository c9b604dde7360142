/**
 * The seed report's "función ruido": a pseudo-random number generator that always
 * returns the same value for the same integer input. The lattice point and the seed are
 * mixed with the MurmurHash3 finaliser in exact 32-bit integer arithmetic (Math.imul), so
 * the value is identical on every JavaScript engine and free of the bias that the classic
 * tutorial hash shows for small coordinates.
 *
 * Returns a value in [-1, 1).
 */
export function integerNoise(x: number, y: number, seed: number): number {
  let h = Math.imul(x | 0, 0x27d4eb2d) ^ Math.imul(y | 0, 0x165667b1) ^ Math.imul(seed | 0, 0x9e3779b1);
  h ^= h >>> 16;
  h = Math.imul(h, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  h ^= h >>> 16;
  return (h >>> 0) / 2147483648 - 1;
}

/** Small seeded generator (mulberry32) for the few places that need a stream of numbers. */
export function seededRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) | 0;
    let t = Math.imul(state ^ (state >>> 15), 1 | state);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
