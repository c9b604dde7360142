import { ISLAND_CENTER, ISLAND_RADIUS, OFFSHORE_DEPTH, seaDepth, shelfWidth } from './bathymetry';
import type { CoastField, CoastSetting, SwellComponentField } from './coastField';
import { type CoastWaveModel, fieldWaveNumber, SHALLOWEST_DEPTH } from './coastWaveModel';
import type { SwellComponentSpec } from './swellSpectrum';

/** Refraction may focus rays into a caustic, where ray theory's amplitude is infinite; it is capped here (a sane Kr). */
export const MAX_REFRACTION_COEFFICIENT = 2.5;
/** Rays launched per texel width of the incoming swell, and ray steps per texel: enough that the ray density is smooth. */
const RAYS_PER_TEXEL = 2;
const STEPS_PER_TEXEL = 2;
/** Passes of the 3×3 binomial filter over the ray density: about a 2-texel radius. */
const SMOOTHING_PASSES = 4;
/** Fast-sweeping rounds (each four sweeps) at most; the lee needs a few more than open water. */
const MAX_SWEEP_ROUNDS = 12;

/**
 * The swell around the island, component by component. Each phase solves the eikonal equation
 * |∇S| = k(h) (geometric optics) for a plane wave arriving from upstream, by fast sweeping
 * (Zhao 2005) on the grid with the island as an obstacle: S is the first arrival, so behind the
 * island, where the waves that wrap round either side meet, S takes the earlier of the two (a
 * kink, not a crossing sea). Its amplitude comes from ray theory: rays are traced from the
 * offshore boundary and their density gives the ray tube's width b, so Kr = √(b0 / b); crossing
 * rays add their energies. Then A = a0 Ks Kr, with Kr capped at MAX_REFRACTION_COEFFICIENT;
 * breaking is left to the sum of the components (coastSwellSlope.ts).
 */
export function buildIslandField(
  setting: CoastSetting,
  resolution: number,
  model: CoastWaveModel,
  components: readonly SwellComponentSpec[],
): CoastField {
  const slope = setting.beachSlope;
  // The grid is shared by every component: its margin is one wavelength of the longest of them.
  const longest = Math.min(...components.map((c) => c.angularFrequency));
  const kLongest = model.waveNumber(longest, OFFSHORE_DEPTH);
  // A square around the island out to where h = OFFSHORE_DEPTH, with a margin of a tenth or one offshore wavelength.
  const reach = ISLAND_RADIUS + shelfWidth(slope);
  const half = reach + Math.max(0.1 * reach, (2 * Math.PI) / kLongest);
  const spacing = (2 * half) / (resolution - 1);
  const originX = ISLAND_CENTER[0] - half;
  const originZ = ISLAND_CENTER[1] - half;
  const n = resolution;
  const floor = { bathymetry: 'island' as const, beachSlope: slope, deepDepth: OFFSHORE_DEPTH };

  const depth = new Float64Array(n * n);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) depth[j * n + i] = seaDepth(floor, originX + i * spacing, originZ + j * spacing);
  }
  const theta0 = (setting.swellDirection * Math.PI) / 180;
  const direction: [number, number] = [Math.cos(theta0), Math.sin(theta0)];

  const islandComponent = (component: SwellComponentSpec): SwellComponentField => {
    const omega = component.angularFrequency;
    const k0 = model.waveNumber(omega, OFFSHORE_DEPTH);
    const k = new Float64Array(n * n);
    // Beyond the shelf the depth is OFFSHORE_DEPTH and k is k0: no need to solve the dispersion relation again.
    for (let t = 0; t < n * n; t++) k[t] = depth[t] >= OFFSHORE_DEPTH ? k0 : fieldWaveNumber(model, omega, depth[t]);
    const phase = eikonalPhase(n, spacing, depth, k, k0, direction, originX, originZ);
    const density = rayDensity(n, spacing, depth, k, direction);
    const cg0 = model.groupVelocity(k0, OFFSHORE_DEPTH);
    const texels = new Float32Array(n * n * 2);
    for (let t = 0; t < n * n; t++) {
      const d = depth[t];
      texels[t * 2] = phase[t];
      if (d <= 0) continue;
      const kr = Math.min(MAX_REFRACTION_COEFFICIENT, Math.sqrt(density[t]));
      const cg = d >= OFFSHORE_DEPTH ? cg0 : model.groupVelocity(k[t], d);
      texels[t * 2 + 1] = component.amplitude * Math.sqrt(cg0 / cg) * kr;
    }
    return { angularFrequency: omega, phaseOffset: component.phaseOffset, texels };
  };

  return { originX, originZ, spacing, resolution, floor, breakerIndex: model.breakerIndex, components: components.map(islandComponent) };
}

/**
 * Fast sweeping for |∇S| = k with Godunov's upwind update (Zhao 2005, Math. Comp. 74, 603–627).
 * The edges the swell comes in through hold the plane wave S = k0 d·x; land is an obstacle.
 * The upwind update is exact for a plane wave over uniform depth, so the open sea stays one.
 * Land texels then get the phase carried on from the water, so bilinear sampling stays smooth.
 */
function eikonalPhase(
  n: number,
  spacing: number,
  depth: Float64Array,
  k: Float64Array,
  k0: number,
  direction: [number, number],
  originX: number,
  originZ: number,
): Float64Array {
  const phase = new Float64Array(n * n).fill(Infinity);
  const fixed = new Uint8Array(n * n);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const inflow =
        (direction[0] > 1e-9 && i === 0) ||
        (direction[0] < -1e-9 && i === n - 1) ||
        (direction[1] > 1e-9 && j === 0) ||
        (direction[1] < -1e-9 && j === n - 1);
      if (!inflow) continue;
      phase[j * n + i] = k0 * (direction[0] * (originX + i * spacing) + direction[1] * (originZ + j * spacing));
      fixed[j * n + i] = 1;
    }
  }
  const update = (i: number, j: number): number => {
    const t = j * n + i;
    if (fixed[t] || depth[t] <= 0) return 0;
    const a = Math.min(i > 0 ? phase[t - 1] : Infinity, i < n - 1 ? phase[t + 1] : Infinity);
    const b = Math.min(j > 0 ? phase[t - n] : Infinity, j < n - 1 ? phase[t + n] : Infinity);
    if (a === Infinity && b === Infinity) return 0;
    const f = k[t] * spacing;
    let next: number;
    if (Math.abs(a - b) >= f) next = Math.min(a, b) + f;
    else next = 0.5 * (a + b + Math.sqrt(2 * f * f - (a - b) * (a - b)));
    if (next >= phase[t]) return 0;
    const change = phase[t] === Infinity ? Infinity : phase[t] - next;
    phase[t] = next;
    return change;
  };
  for (let round = 0; round < MAX_SWEEP_ROUNDS; round++) {
    let largest = 0;
    for (const [di, dj] of [
      [1, 1],
      [-1, 1],
      [-1, -1],
      [1, -1],
    ]) {
      for (let jj = 0; jj < n; jj++) {
        const j = dj > 0 ? jj : n - 1 - jj;
        for (let ii = 0; ii < n; ii++) largest = Math.max(largest, update(di > 0 ? ii : n - 1 - ii, j));
      }
    }
    if (largest < 1e-9) break;
  }
  fillLand(n, phase);
  return phase;
}

/** Gives each unreached (land) texel, ring by ring from the water, the mean of its neighbours' phases carried on linearly. */
function fillLand(n: number, phase: Float64Array): void {
  let pending: number[] = [];
  for (let t = 0; t < n * n; t++) if (phase[t] === Infinity) pending.push(t);
  const carried = (i: number, j: number, di: number, dj: number): number => {
    const i1 = i + di;
    const j1 = j + dj;
    if (i1 < 0 || j1 < 0 || i1 >= n || j1 >= n) return Infinity;
    const near = phase[j1 * n + i1];
    const i2 = i1 + di;
    const j2 = j1 + dj;
    const far = near !== Infinity && i2 >= 0 && j2 >= 0 && i2 < n && j2 < n ? phase[j2 * n + i2] : Infinity;
    return far === Infinity ? near : 2 * near - far;
  };
  while (pending.length > 0) {
    const ring: [number, number][] = [];
    const rest: number[] = [];
    for (const t of pending) {
      const i = t % n;
      const j = (t - i) / n;
      let sum = 0;
      let count = 0;
      for (const value of [carried(i, j, 1, 0), carried(i, j, -1, 0), carried(i, j, 0, 1), carried(i, j, 0, -1)]) {
        if (value === Infinity) continue;
        sum += value;
        count++;
      }
      if (count > 0) ring.push([t, sum / count]);
      else rest.push(t);
    }
    if (ring.length === 0) break;
    for (const [t, value] of ring) phase[t] = value;
    pending = rest;
  }
}

/**
 * Traces rays of the swell across the grid and returns, per texel, Kr² = b0 / b: the rays'
 * summed path length in a texel over its area is 1 / b, the ray density. Rays follow
 *   dx/ds = (cos θ, sin θ),  dθ/ds = ∇(ln k) · (−sin θ, cos θ),
 * turning towards larger k (shallower water), and stop at the shoreline, where they break.
 * Path length is splatted bilinearly, and the density is smoothed (SMOOTHING_PASSES binomial passes).
 */
function rayDensity(n: number, spacing: number, depth: Float64Array, k: Float64Array, direction: [number, number]): Float64Array {
  // Per texel, interleaved so one bilinear look-up reads all three: depth, and ∇ ln k by central differences.
  const medium = new Float64Array(n * n * 3);
  const lnk = (i: number, j: number): number => Math.log(k[Math.min(n - 1, Math.max(0, j)) * n + Math.min(n - 1, Math.max(0, i))]);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const t = (j * n + i) * 3;
      medium[t] = depth[j * n + i];
      medium[t + 1] = (lnk(i + 1, j) - lnk(i - 1, j)) / ((i === 0 || i === n - 1 ? 1 : 2) * spacing);
      medium[t + 2] = (lnk(i, j + 1) - lnk(i, j - 1)) / ((j === 0 || j === n - 1 ? 1 : 2) * spacing);
    }
  }
  // The medium at texel coordinates (u, v), clamped to the grid, into `local` ([depth, ∂x ln k, ∂z ln k]).
  const local = new Float64Array(3);
  const look = (u: number, v: number): void => {
    const i0 = Math.min(n - 2, Math.max(0, Math.floor(u)));
    const j0 = Math.min(n - 2, Math.max(0, Math.floor(v)));
    const fu = Math.min(1, Math.max(0, u - i0));
    const fv = Math.min(1, Math.max(0, v - j0));
    const w00 = (1 - fu) * (1 - fv);
    const w10 = fu * (1 - fv);
    const w01 = (1 - fu) * fv;
    const w11 = fu * fv;
    const t = (j0 * n + i0) * 3;
    const up = n * 3;
    for (let c = 0; c < 3; c++)
      local[c] = w00 * medium[t + c] + w10 * medium[t + 3 + c] + w01 * medium[t + up + c] + w11 * medium[t + up + 3 + c];
  };

  const pathLength = new Float64Array(n * n);
  const rayGap = spacing / RAYS_PER_TEXEL;
  const step = spacing / STEPS_PER_TEXEL;
  const stepTexels = 1 / STEPS_PER_TEXEL;
  // Rays start on a line across the swell, upstream of the whole grid, a texel beyond its edge; they run in texel units.
  const centre = (n - 1) / 2;
  const halfWidth = centre * (Math.abs(direction[0]) + Math.abs(direction[1])) + 1;
  const theta0 = Math.atan2(direction[1], direction[0]);
  for (let offset = -halfWidth; offset <= halfWidth; offset += 1 / RAYS_PER_TEXEL) {
    let u = centre - (halfWidth + 1) * direction[0] - offset * direction[1];
    let v = centre - (halfWidth + 1) * direction[1] + offset * direction[0];
    let theta = theta0;
    let entered = false;
    for (let s = 0; s < 8 * n * STEPS_PER_TEXEL; s++) {
      const inside = u >= -1 && v >= -1 && u <= n && v <= n;
      if (!inside) {
        if (entered || s * stepTexels > 4 * halfWidth) break;
      } else {
        entered = true;
        look(u, v);
        if (local[0] < SHALLOWEST_DEPTH) break;
        // A ray that has turned back (trapped on the shelf, circling the island) runs against the drawn
        // wave train, whose phase is the first arrival: its energy is not part of that train.
        if (Math.cos(theta - theta0) < 0) break;
        splat(pathLength, n, u, v, step);
      }
      if (!inside) look(u, v);
      // dθ/ds = ∇ln k · (−sin θ, cos θ), by the midpoint rule: half a step to the middle, then the whole step from there.
      const thetaMid = theta + 0.5 * step * (-Math.sin(theta) * local[1] + Math.cos(theta) * local[2]);
      look(u + 0.5 * stepTexels * Math.cos(theta), v + 0.5 * stepTexels * Math.sin(theta));
      theta += step * (-Math.sin(thetaMid) * local[1] + Math.cos(thetaMid) * local[2]);
      u += stepTexels * Math.cos(thetaMid);
      v += stepTexels * Math.sin(thetaMid);
    }
  }
  // Path length per area times the rays' spacing is b0 / b. Then smoothing: the rays sample the
  // tube unevenly (their spacing drifts against the texels'), which a few binomial passes even out.
  let density: Float64Array = pathLength.map((length) => (length * rayGap) / (spacing * spacing));
  for (let pass = 0; pass < SMOOTHING_PASSES; pass++) density = smoothOverWater(n, density, depth);
  return density;
}

/** One pass of a 3×3 binomial filter over the water's texels (land neither gives nor takes). */
function smoothOverWater(n: number, values: Float64Array, depth: Float64Array): Float64Array {
  const out = new Float64Array(n * n);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      if (depth[j * n + i] <= 0) continue;
      let sum = 0;
      let weight = 0;
      for (let dj = -1; dj <= 1; dj++) {
        for (let di = -1; di <= 1; di++) {
          const ii = i + di;
          const jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= n || jj >= n || depth[jj * n + ii] <= 0) continue;
          const w = (2 - Math.abs(di)) * (2 - Math.abs(dj));
          sum += w * values[jj * n + ii];
          weight += w;
        }
      }
      out[j * n + i] = sum / weight;
    }
  }
  return out;
}

/** Adds `length` of ray path at texel coordinates (u, v), shared bilinearly among the four nearest texels inside the grid. */
function splat(values: Float64Array, n: number, u: number, v: number, length: number): void {
  const i0 = Math.floor(u);
  const j0 = Math.floor(v);
  const fu = u - i0;
  const fv = v - j0;
  const add = (i: number, j: number, w: number): void => {
    if (i >= 0 && j >= 0 && i < n && j < n) values[j * n + i] += w * length;
  };
  add(i0, j0, (1 - fu) * (1 - fv));
  add(i0 + 1, j0, fu * (1 - fv));
  add(i0, j0 + 1, (1 - fu) * fv);
  add(i0 + 1, j0 + 1, fu * fv);
}
