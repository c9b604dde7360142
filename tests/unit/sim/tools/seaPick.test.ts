import { describe, expect, it } from 'vitest';
import { pickSea, rayPlane, type Vec3 } from '../../../../src/sim/tools/seaPick';

/** A swell of 1.5 m amplitude and 20 m wavelength along x, crossed by a shorter one along z. */
const wavy = (x: number, z: number) => 1.5 * Math.sin((2 * Math.PI * x) / 20) + 0.4 * Math.cos((2 * Math.PI * z) / 7);
const WAVY_MAX = 1.9;

/** The first crossing found by brute force: 1 mm steps along the ray. */
function bruteForce(origin: Vec3, direction: Vec3, height: (x: number, z: number) => number, maxDistance: number): number | null {
  const length = Math.hypot(...direction);
  const d = direction.map((c) => c / length);
  const gap = (s: number) => origin[1] + s * d[1] - height(origin[0] + s * d[0], origin[2] + s * d[2]);
  const above = gap(0) > 0;
  for (let s = 0; s < maxDistance; s += 0.001) if (gap(s) > 0 !== above) return s;
  return null;
}

describe('the point a click picks on the sea', () => {
  it('on a flat sea is the ray meeting the plane y = 0, exactly', () => {
    const origin: Vec3 = [3, 12, -4];
    const direction: Vec3 = [0.3, -1, -0.8];
    const flat = pickSea(origin, direction, () => 0, { maxHeight: 0 })!;
    const plane = rayPlane(origin, direction)!;
    expect(flat.x).toBeCloseTo(plane.x, 9);
    expect(flat.z).toBeCloseTo(plane.z, 9);
    expect(flat.y).toBe(0);
    // 12 m down at a slope of 1 in |(0.3, −1, −0.8)|: s = 12 · 1.3153… / 1.
    expect(flat.distance).toBeCloseTo(12 * Math.hypot(0.3, 1, 0.8), 9);
  });

  it('on a wavy sea lies on the surface and is the first crossing along the ray (seeded rays, brute force)', () => {
    let seed = 7;
    const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    for (let i = 0; i < 40; i++) {
      const origin: Vec3 = [random() * 100 - 50, 2.5 + random() * 20, random() * 100 - 50];
      // Down at 2° to 60°: grazing rays pass over crests before they meet the sea.
      const dip = ((2 + random() * 58) * Math.PI) / 180;
      const heading = random() * 2 * Math.PI;
      const direction: Vec3 = [Math.cos(dip) * Math.cos(heading), -Math.sin(dip), Math.cos(dip) * Math.sin(heading)];
      const hit = pickSea(origin, direction, wavy, { maxHeight: WAVY_MAX, step: 0.1, maxDistance: 1500 });
      const brute = bruteForce(origin, direction, wavy, 1500);
      expect(hit === null, `ray ${i}`).toBe(brute === null);
      if (!hit || brute === null) continue;
      expect(Math.abs(hit.y - wavy(hit.x, hit.z)), `ray ${i}`).toBeLessThan(1e-9);
      expect(Math.abs(origin[1] + hit.distance * direction[1] - hit.y), `ray ${i} on the ray`).toBeLessThan(1e-6);
      expect(Math.abs(hit.distance - brute), `ray ${i}`).toBeLessThan(0.002);
    }
  });

  it('misses when the ray looks up into the sky, and from below the water meets the surface above', () => {
    expect(pickSea([0, 5, 0], [0.2, 0.5, 1], wavy, { maxHeight: WAVY_MAX })).toBeNull();
    expect(pickSea([0, 5, 0], [1, 0, 0], wavy, { maxHeight: WAVY_MAX })).toBeNull();
    const below = pickSea([4, -6, 2], [0.1, 1, 0.2], wavy, { maxHeight: WAVY_MAX })!;
    expect(Math.abs(below.y - wavy(below.x, below.z))).toBeLessThan(1e-9);
    expect(below.y).toBeGreaterThan(-WAVY_MAX);
  });

  it('control: the mean plane alone misses the wavy surface by up to metres on a grazing ray', () => {
    const origin: Vec3 = [0, 8, 0];
    const direction: Vec3 = [1, -0.12, 0.2];
    const hit = pickSea(origin, direction, wavy, { maxHeight: WAVY_MAX })!;
    const plane = rayPlane(origin, direction)!;
    expect(Math.hypot(plane.x - hit.x, plane.z - hit.z)).toBeGreaterThan(1);
  });
});
