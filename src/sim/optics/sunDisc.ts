/**
 * The sun's disc (angular radius 0.2666°, 4.65 mrad) as a slope variance: a uniform disc of
 * radius r has r²/4 of variance per axis; the half vector moves by half the angle, so the
 * facets that catch some of the disc spread by (r/2)²/4 per axis, r²/8 in all. The floor of
 * the roughness: a mirror still reflects a sun of finite size.
 */
export const SUN_DISC_SLOPE_VARIANCE = 0.00465 ** 2 / 8;
