// Writes public/models/boat.glb, the low-poly sailing boat that rides the waves:
// `npx tsx scripts/build/make-boat.ts` (or `npm run boat`). Model frame: metres, bow towards −z,
// starboard towards +x, the design waterline at y = 0 (the pose puts y = 0 on the surface).
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { FlatMeshBuilder, type Vec3 } from './glbWriter';

const OUT = join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'public', 'models', 'boat.glb');

/** Hull stations from bow to stern: half beam at the deck, deck height and keel depth, metres. */
const STATIONS: { z: number; halfBeam: number; deck: number; keel: number }[] = [
  { z: -4.0, halfBeam: 0.0, deck: 1.0, keel: -0.05 },
  { z: -3.2, halfBeam: 0.55, deck: 0.93, keel: -0.35 },
  { z: -2.2, halfBeam: 0.95, deck: 0.86, keel: -0.5 },
  { z: -1.0, halfBeam: 1.2, deck: 0.8, keel: -0.6 },
  { z: 0.5, halfBeam: 1.3, deck: 0.76, keel: -0.62 },
  { z: 2.0, halfBeam: 1.25, deck: 0.76, keel: -0.55 },
  { z: 3.3, halfBeam: 1.1, deck: 0.78, keel: -0.4 },
  { z: 4.0, halfBeam: 0.95, deck: 0.8, keel: -0.25 },
];

/** One hull cross-section, port deck edge round the keel to the starboard deck edge. */
function section(s: (typeof STATIONS)[number]): Vec3[] {
  const { z, halfBeam: b, deck, keel } = s;
  const port: Vec3[] = [
    [-b, deck, z],
    [-0.985 * b, 0.32, z],
    [-0.96 * b, 0.12, z],
    [-0.62 * b, 0.72 * keel, z],
  ];
  const starboard = port.map(([x, y]) => [-x, y, z] as Vec3).reverse();
  return [...port, [0, keel, z], ...starboard];
}

const boat = new FlatMeshBuilder();
const hull = boat.addMaterial({ name: 'Hull', color: '#1f3f66', metallic: 0.0, roughness: 0.45 });
const boot = boat.addMaterial({ name: 'Boot stripe', color: '#b8322a', metallic: 0.0, roughness: 0.5 });
const deck = boat.addMaterial({ name: 'Teak deck', color: '#a9784a', metallic: 0.0, roughness: 0.8 });
const cabin = boat.addMaterial({ name: 'Cabin', color: '#eeece4', metallic: 0.0, roughness: 0.55 });
const glass = boat.addMaterial({ name: 'Windows', color: '#1a2630', metallic: 0.3, roughness: 0.15 });
const spar = boat.addMaterial({ name: 'Mast and boom', color: '#c4c8cc', metallic: 0.2, roughness: 0.4 });
const sail = boat.addMaterial({ name: 'Sails', color: '#f4f1e8', metallic: 0.0, roughness: 0.9, doubleSided: true });

// Hull skin between consecutive sections; the band just above the waterline (0.12 to 0.32 m) is the boot stripe.
const sections = STATIONS.map(section);
for (let k = 0; k + 1 < sections.length; k++) {
  const a = sections[k];
  const c = sections[k + 1];
  const inside: Vec3 = [0, 0.3, (STATIONS[k].z + STATIONS[k + 1].z) / 2];
  for (let i = 0; i + 1 < a.length; i++) {
    const material = i === 1 || i === a.length - 3 ? boot : hull;
    boat.quad(material, a[i], a[i + 1], c[i + 1], c[i], inside);
  }
}
const transom = sections[sections.length - 1];
boat.polygon(hull, transom, [0, 0.3, 3.5]);

// Deck: strips across the beam between stations, facing up.
for (let k = 0; k + 1 < sections.length; k++) {
  const a = sections[k];
  const c = sections[k + 1];
  const below: Vec3 = [0, -5, (STATIONS[k].z + STATIONS[k + 1].z) / 2];
  boat.quad(deck, a[0], a[a.length - 1], c[c.length - 1], c[0], below);
}

// Cabin: a box with tumblehome sides and a raked front.
const cabinBottom = 0.74;
const cabinTop = 1.5;
const cabinCorners = {
  bfl: [-0.8, cabinBottom, -0.8] as Vec3,
  bfr: [0.8, cabinBottom, -0.8] as Vec3,
  bal: [-0.8, cabinBottom, 2.2] as Vec3,
  bar: [0.8, cabinBottom, 2.2] as Vec3,
  tfl: [-0.65, cabinTop, -0.3] as Vec3,
  tfr: [0.65, cabinTop, -0.3] as Vec3,
  tal: [-0.65, cabinTop, 2.1] as Vec3,
  tar: [0.65, cabinTop, 2.1] as Vec3,
};
const cabinInside: Vec3 = [0, 1.1, 0.8];
const { bfl, bfr, bal, bar, tfl, tfr, tal, tar } = cabinCorners;
boat.quad(cabin, bfl, bfr, tfr, tfl, cabinInside);
boat.quad(cabin, bal, bar, tar, tal, cabinInside);
boat.quad(cabin, bfl, bal, tal, tfl, cabinInside);
boat.quad(cabin, bfr, bar, tar, tfr, cabinInside);
boat.quad(cabin, tfl, tfr, tar, tal, cabinInside);

// Windows: dark panes a centimetre proud of the cabin sides and front.
const sideX = (y: number) => 0.8 - ((y - cabinBottom) / (cabinTop - cabinBottom)) * 0.15 + 0.012;
const frontZ = (y: number) => -0.8 + ((y - cabinBottom) / (cabinTop - cabinBottom)) * 0.5 - 0.012;
for (const sign of [-1, 1]) {
  for (const [z0, z1] of [
    [-0.35, 0.55],
    [0.85, 1.8],
  ]) {
    const y0 = 1.02;
    const y1 = 1.3;
    boat.quad(
      glass,
      [sign * sideX(y0), y0, z0],
      [sign * sideX(y0), y0, z1],
      [sign * sideX(y1), y1, z1],
      [sign * sideX(y1), y1, z0],
      cabinInside,
    );
  }
}
for (const [x0, x1] of [
  [-0.6, -0.08],
  [0.08, 0.6],
]) {
  const y0 = 1.0;
  const y1 = 1.3;
  boat.quad(glass, [x0, y0, frontZ(y0)], [x1, y0, frontZ(y0)], [x1, y1, frontZ(y1)], [x0, y1, frontZ(y1)], cabinInside);
}

/** A tapered square spar from `from` to `to`, with half widths at each end. */
function sparBetween(from: Vec3, to: Vec3, halfFrom: number, halfTo: number): void {
  const alongY = Math.abs(to[1] - from[1]) > Math.abs(to[2] - from[2]);
  const offsets = (h: number): Vec3[] =>
    alongY
      ? [
          [-h, 0, -h],
          [h, 0, -h],
          [h, 0, h],
          [-h, 0, h],
        ]
      : [
          [-h, -h, 0],
          [h, -h, 0],
          [h, h, 0],
          [-h, h, 0],
        ];
  const add = (p: Vec3, o: Vec3): Vec3 => [p[0] + o[0], p[1] + o[1], p[2] + o[2]];
  const a = offsets(halfFrom).map((o) => add(from, o));
  const b = offsets(halfTo).map((o) => add(to, o));
  const middle: Vec3 = [(from[0] + to[0]) / 2, (from[1] + to[1]) / 2, (from[2] + to[2]) / 2];
  for (let i = 0; i < 4; i++) boat.quad(spar, a[i], a[(i + 1) % 4], b[(i + 1) % 4], b[i], middle);
  boat.polygon(spar, a, middle);
  boat.polygon(spar, b, middle);
}

const mastZ = -0.2;
sparBetween([0, cabinTop, mastZ], [0, 9.6, mastZ], 0.07, 0.045);
sparBetween([0, 2.05, mastZ + 0.07], [0, 2.05, 3.4], 0.05, 0.04);

// Mainsail on the boom and the jib to the stem head: flat triangles, seen from both sides.
const mainsail: Vec3[] = [
  [0, 2.12, mastZ + 0.1],
  [0, 9.3, mastZ + 0.08],
  [0, 2.12, 3.3],
];
const jib: Vec3[] = [
  [0, 8.4, mastZ - 0.08],
  [0, 1.2, -3.8],
  [0, 1.75, -0.75],
];
boat.polygon(sail, mainsail, [1, 0, 0]);
boat.polygon(sail, jib, [1, 0, 0]);

mkdirSync(dirname(OUT), { recursive: true });
const glb = boat.toGlb('Boat');
writeFileSync(OUT, glb);
console.log(`Wrote ${OUT} (${glb.length} bytes).`);
