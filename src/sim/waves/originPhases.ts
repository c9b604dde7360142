/**
 * What a wave model's per-pixel shading needs to evaluate its waves at points relative to
 * the render origin (src/render/ocean/renderOrigin.ts) instead of at absolute grid points. An
 * interpolated float32 grid point 10⁶ m out is rounded to 6 cm, so normals evaluated there
 * came in 6 cm blocks: a faint checker in the sun glint. Relative points are a few km at
 * most (exact to 0.2 mm); the origin's share of every phase is added here, in double
 * precision, once per frame.
 */

export interface OriginWave {
  /** Wavevector in cycles per metre (the Gerstner table's cₓ, c_z). */
  cx: number;
  cz: number;
}

function fract(x: number): number {
  return x - Math.floor(x);
}

/**
 * Each Gerstner wave's time phase τᵢ (turns, from gerstnerTimePhases) with the origin's
 * share cₓ oₓ + c_z o_z folded in: the shader's angle fract(cₓ x) + fract(c_z z) + τ at
 * x = oₓ + rₓ equals fract(cₓ rₓ) + fract(c_z r_z) + τ′ modulo whole turns.
 */
export function gerstnerOriginPhases(
  waves: readonly OriginWave[],
  timePhases: ArrayLike<number>,
  originX: number,
  originZ: number,
): Float64Array {
  const phases = new Float64Array(waves.length);
  for (let i = 0; i < waves.length; i++) {
    // Each product reduced alone: cₓ oₓ reaches 10⁶ turns, which a double still holds to 1e-10.
    phases[i] = fract(timePhases[i] + fract(waves[i].cx * originX) + fract(waves[i].cz * originZ));
  }
  return phases;
}

/**
 * Where the origin falls in a repeating tile of n texels per `size` metres, in texels,
 * within [0, n): a field read at u = r n / size + this is the field at the origin + r.
 */
export function tileOriginTexels(size: number, n: number, originX: number, originZ: number): [number, number] {
  const wrap = (metres: number) => {
    const turns = fract(metres / size);
    // fract can round up to exactly 1 for a tiny negative argument.
    return turns * n >= n ? 0 : turns * n;
  };
  return [wrap(originX), wrap(originZ)];
}
