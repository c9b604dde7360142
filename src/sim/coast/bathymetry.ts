/**
 * The sea floor under the coast: how deep the water is at a world point. Three shapes, chosen
 * by the `bathymetry` parameter:
 * - `deep`: no coast; the sea is as deep as the `depth` parameter everywhere.
 * - `beach`: straight, parallel depth contours along z. The bed is a plane that rises towards
 *   +x with slope `beachSlope` from OFFSHORE_DEPTH to the shoreline at x = BEACH_SHORE_X, and
 *   goes on rising, as sand, up to a dune of DUNE_HEIGHT.
 * - `island`: a round island of radius ISLAND_RADIUS at ISLAND_CENTER, on a conical shelf
 *   that falls away from its shore with the same slope to OFFSHORE_DEPTH; its land rises as a
 *   hill to ISLAND_HEIGHT.
 * Depths are positive in water and negative on land (minus the ground's height above sea level).
 */
export type Bathymetry = 'deep' | 'beach' | 'island';
export const BATHYMETRIES: readonly Bathymetry[] = ['deep', 'beach', 'island'];

/** The water's depth beyond the slope, metres: waves of up to 10 s barely feel a 60 m bottom (k h > 1.2). */
export const OFFSHORE_DEPTH = 60;
/** Where the beach's shoreline runs (the line x = BEACH_SHORE_X), metres east of the world's origin. */
export const BEACH_SHORE_X = 400;
/** How high the beach's sand rises behind the shore, metres. */
export const DUNE_HEIGHT = 4;
/** The island: its centre, its radius at the waterline and the top of its hill, metres. */
export const ISLAND_CENTER: readonly [number, number] = [700, 0];
export const ISLAND_RADIUS = 120;
export const ISLAND_HEIGHT = 30;

export interface SeaFloor {
  bathymetry: Bathymetry;
  /** Slope of the bed, rise over run (0.005–0.1). */
  beachSlope: number;
  /** The open sea's depth for `deep`, metres (the `depth` parameter). */
  deepDepth: number;
}

/** The bed's height above the still water line would be −depth; this is the depth (m, ≤ 0 on land) at world (x, z). */
export function seaDepth(floor: SeaFloor, x: number, z: number): number {
  switch (floor.bathymetry) {
    case 'deep':
      return floor.deepDepth;
    case 'beach':
      return slopedDepth(BEACH_SHORE_X - x, floor.beachSlope, DUNE_HEIGHT);
    case 'island': {
      const fromShore = Math.hypot(x - ISLAND_CENTER[0], z - ISLAND_CENTER[1]) - ISLAND_RADIUS;
      return slopedDepth(fromShore, floor.beachSlope, ISLAND_HEIGHT);
    }
  }
}

/**
 * Depth at `seaward` metres from the shoreline (negative: inland) on a plane of `slope`,
 * between OFFSHORE_DEPTH out at sea and `landHeight` above the water inland.
 */
function slopedDepth(seaward: number, slope: number, landHeight: number): number {
  return Math.min(OFFSHORE_DEPTH, Math.max(-landHeight, seaward * slope));
}

/** The distance from the shoreline to where the bed reaches OFFSHORE_DEPTH, metres: the width of the sloping shelf. */
export function shelfWidth(slope: number): number {
  return OFFSHORE_DEPTH / slope;
}

/** ∇h at world (x, z), per metre: the slope of seaDepth where it is a plane (0 on the flat sea, the dune's top and the hill's). */
export function seaDepthGradient(floor: SeaFloor, x: number, z: number): [number, number] {
  switch (floor.bathymetry) {
    case 'deep':
      return [0, 0];
    case 'beach': {
      const seaward = BEACH_SHORE_X - x;
      return onSlope(seaward, floor.beachSlope, DUNE_HEIGHT) ? [-floor.beachSlope, 0] : [0, 0];
    }
    case 'island': {
      const dx = x - ISLAND_CENTER[0];
      const dz = z - ISLAND_CENTER[1];
      const r = Math.hypot(dx, dz);
      if (r === 0 || !onSlope(r - ISLAND_RADIUS, floor.beachSlope, ISLAND_HEIGHT)) return [0, 0];
      return [(floor.beachSlope * dx) / r, (floor.beachSlope * dz) / r];
    }
  }
}

/** Whether a point `seaward` metres from the shoreline lies on the sloping plane, between the land's top and OFFSHORE_DEPTH. */
function onSlope(seaward: number, slope: number, landHeight: number): boolean {
  const depth = seaward * slope;
  return depth > -landHeight && depth < OFFSHORE_DEPTH;
}
