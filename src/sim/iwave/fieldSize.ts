// The app's interactive field in numbers, apart from its code: the ocean's shaders and culling read them before the field runs.
/** The app's field: 256 × 256 texels of 0.5 m, a square 128 m across around the camera's focus. */
export const IWAVE_GRID_SIZE = 256;
export const IWAVE_SPACING = 0.5;
/** Seconds of simulation time per step: the field advances in these whatever the frame rate. */
export const IWAVE_STEP = 1 / 60;
/** Light damping everywhere, 1/s: left alone, waves lose a factor e of their height in 100 s. */
export const IWAVE_DAMPING = 0.02;
/** The most steps a jump forward runs (10 s); past it the field restarts calm that far back. */
export const IWAVE_CATCH_UP_STEPS = 600;
/** The tallest bump a disturbance may add or dig, metres, and the widest, metres. */
export const IWAVE_MAX_HEIGHT = 2;
export const IWAVE_MAX_RADIUS = 10;
