/**
 * The god rays follow each line of sight this far, metres (fog hides what is beyond). Shared
 * with shaders/underwater.frag as the define GOD_RAY_RANGE: the shaft light's window (shaftLightTile.ts) must cover
 * every point the march reads.
 */
export const GOD_RAY_RANGE = 60;
